#include "segment/exact_seed_walk.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <mutex>
#include <numeric>
#include <optional>
#include <thread>
#include <utility>

#include "meshseg/status_macros.h"

namespace meshseg::segment_internal {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kStopCheckStride = 1024;
// A stretch is walked ahead only if it spans at least this many positions
// of the seed order: at its start, the seeds up to the next face border are
// walked on a guess of what holds them, which may be wrong.
constexpr int kMinStretch = 64;

double Dihedral(const FacetMesh& fm, int f, int g) {
  return std::atan2(fm.normal[f].cross(fm.normal[g]).norm(), fm.normal[f].dot(fm.normal[g]));
}

// Facets in the order they seed (exact_seed_walk.h).
std::vector<int> SeedOrder(const FacetMesh& fm) {
  const int n = fm.facet_count();
  std::vector<float> sharpest(n, 0.0f);
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 4096), [&](const tbb::blocked_range<int>& range) {
    for (int f = range.begin(); f < range.end(); ++f) {
      for (const int g : fm.across[f]) {
        if (g >= 0) sharpest[f] = std::max(sharpest[f], static_cast<float>(Dihedral(fm, f, g)));
      }
    }
  });
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  // (sharpest, index) is a strict total order: the sort is the stable one.
  tbb::parallel_sort(order.begin(), order.end(), [&](int a, int b) {
    return sharpest[a] < sharpest[b] || (sharpest[a] == sharpest[b] && a < b);
  });
  return order;
}

// What facet f gives as a seed: its plane, and its curved hypothesis unless
// the plane holds every neighbour across an edge flatter than the crease.
struct Seeded {
  std::optional<Hypothesis> plane;
  std::optional<Hypothesis> curved;
};

Seeded SeedAt(const FacetMesh& fm, int f, double tau) {
  // Isolated: a thread waiting inside the curved fits' parallel loop takes
  // up no other work of the walk meanwhile (a walk ahead would hold it).
  return tbb::this_task_arena::isolate([&] {
    const double crease = kSeedCreaseDeg * kPi / 180.0;
    Seeded out;
    out.plane = PlaneAt(fm, f, tau);
    bool flat_around = out.plane.has_value();
    for (const int g : fm.across[f]) {
      if (!flat_around) break;
      if (g < 0 || fm.normal[g].isZero() || Dihedral(fm, f, g) >= crease) continue;
      flat_around = std::binary_search(out.plane->support.begin(), out.plane->support.end(), g);
    }
    if (!flat_around) out.curved = CurvedAt(fm, f, tau);
    return out;
  });
}

// Positions [start, end) of the seed order walked ahead, to stop at `limit`
// (where the next stretch starts).
struct Stretch {
  int start = 0;
  std::atomic<int> end{0};
  std::atomic<int> limit{0};
  std::atomic<bool> walking{true};
};

class Walk {
 public:
  Walk(const FacetMesh& fm, double tau)
      : fm_(fm),
        tau_(tau),
        order_(SeedOrder(fm)),
        n_(fm.facet_count()),
        covered_(n_),
        claimed_(n_),
        kept_(n_) {}

  ~Walk() {
    for (std::atomic<Seeded*>& kept : kept_) delete kept.load();
  }

  absl::StatusOr<std::vector<Hypothesis>> Run(const RunContext& ctx) {
    tbb::task_group ahead;
    const int helpers = tbb::this_task_arena::max_concurrency() - 1;
    for (int i = 0; i < helpers; ++i) ahead.run([this] { WalkAhead(); });
    absl::StatusOr<std::vector<Hypothesis>> out = Seed(ctx);
    done_.store(true);
    ahead.wait();
    return out;
  }

 private:
  // The walk itself, in order.
  absl::StatusOr<std::vector<Hypothesis>> Seed(const RunContext& ctx) {
    std::vector<Hypothesis> out;
    for (int k = 0; k < n_; ++k) {
      position_.store(k, std::memory_order_relaxed);
      if (k % kStopCheckStride == 0) {
        MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("segment"));
        ctx.Progress("segment", 0.8 * k / n_);
      }
      const int f = order_[k];
      if (covered_[f].load(std::memory_order_relaxed)) continue;
      Seeded own;
      Seeded* seeded = kept_[f].load(std::memory_order_acquire);
      if (seeded == nullptr) {
        if (claimed_[f].exchange(1, std::memory_order_acq_rel) == 0) {
          own = SeedAt(fm_, f, tau_);
          seeded = &own;
        } else {  // being computed ahead
          while ((seeded = kept_[f].load(std::memory_order_acquire)) == nullptr) {
            std::this_thread::yield();
          }
        }
      }
      covered_[f].store(1, std::memory_order_relaxed);
      for (std::optional<Hypothesis>* h : {&seeded->plane, &seeded->curved}) {
        if (!*h) continue;
        for (const int g : (*h)->support) covered_[g].store(1, std::memory_order_relaxed);
        out.push_back(*std::move(*h));
      }
    }
    return out;
  }

  // One helper: walks stretches ahead until none is worth it.
  void WalkAhead() {
    // held[f] == stamp: f is held by a hypothesis of this stretch.
    std::vector<int> held(n_, 0);
    for (int stamp = 1; !done_.load(); ++stamp) {
      Stretch* stretch = NextStretch();
      if (stretch == nullptr) return;
      WalkStretch(stretch, stamp, &held);
    }
  }

  // Walks `stretch` as the walk would if nothing before it held its facets
  // (but what the walk holds already), keeping each seed's result, until it
  // reaches its limit, a seed taken by the walk or another stretch, or the
  // walk catches up with it.
  void WalkStretch(Stretch* stretch, int stamp, std::vector<int>* held) {
    for (int j = stretch->start; j < n_; ++j) {
      if (done_.load(std::memory_order_relaxed) ||
          j >= stretch->limit.load(std::memory_order_relaxed) ||
          j <= position_.load(std::memory_order_relaxed)) {
        break;
      }
      const int f = order_[j];
      if (!covered_[f].load(std::memory_order_relaxed) && (*held)[f] != stamp) {
        if (claimed_[f].exchange(1, std::memory_order_acq_rel) != 0) break;
        auto seeded = std::make_unique<Seeded>(SeedAt(fm_, f, tau_));
        (*held)[f] = stamp;
        for (const std::optional<Hypothesis>* h : {&seeded->plane, &seeded->curved}) {
          if (!*h) continue;
          for (const int g : (*h)->support) (*held)[g] = stamp;
        }
        kept_[f].store(seeded.release(), std::memory_order_release);
      }
      stretch->end.store(j + 1, std::memory_order_relaxed);
    }
    stretch->walking.store(false);
  }

  // The second half of the longest stretch that the walk, or a stretch
  // walking ahead, has left before the next stretch (each keeps the first
  // half); nullptr if none is kMinStretch long.
  Stretch* NextStretch() {
    std::lock_guard<std::mutex> lock(mutex_);
    const int k = position_.load();
    std::erase_if(stretches_, [&](const std::unique_ptr<Stretch>& s) {
      return !s->walking.load() && s->end.load() <= k;
    });
    int best_from = 0, best_to = 0;
    Stretch* best_runner = nullptr;
    auto consider = [&](int from, int to, Stretch* runner) {
      if (to - from > best_to - best_from) best_from = from, best_to = to, best_runner = runner;
    };
    // The walk: past the stretches it has reached, unless one of them is
    // still walking ahead of it.
    int walk_from = k, walk_to = n_;
    bool walk_leads = true;
    for (const std::unique_ptr<Stretch>& s : stretches_) {
      if (s->start > walk_from) {
        walk_to = s->start;
        break;
      }
      walk_from = std::max(walk_from, s->end.load());
      walk_leads = walk_leads && !s->walking.load();
    }
    if (walk_leads) consider(walk_from, walk_to, nullptr);
    for (std::size_t i = 0; i < stretches_.size(); ++i) {
      Stretch& s = *stretches_[i];
      if (!s.walking.load()) continue;
      const int to = i + 1 < stretches_.size() ? stretches_[i + 1]->start : n_;
      consider(std::max(s.end.load(), k), std::min(to, s.limit.load()), &s);
    }
    if ((best_to - best_from) / 2 < kMinStretch) return nullptr;
    const int start = best_from + (best_to - best_from) / 2;
    if (best_runner != nullptr) best_runner->limit.store(start);
    auto stretch = std::make_unique<Stretch>();
    stretch->start = start;
    stretch->end.store(start);
    stretch->limit.store(best_to);
    Stretch* out = stretch.get();
    stretches_.insert(
        std::upper_bound(stretches_.begin(), stretches_.end(), start,
                         [](int at, const std::unique_ptr<Stretch>& s) { return at < s->start; }),
        std::move(stretch));
    return out;
  }

  const FacetMesh& fm_;
  const double tau_;
  const std::vector<int> order_;
  const int n_;
  std::vector<std::atomic<char>> covered_;  // held by a hypothesis of the walk
  std::vector<std::atomic<char>> claimed_;  // a seed computed or being computed
  std::vector<std::atomic<Seeded*>> kept_;  // results computed ahead (owned)
  std::atomic<int> position_{0};            // the walk's position in order_
  std::atomic<bool> done_{false};
  std::mutex mutex_;
  std::vector<std::unique_ptr<Stretch>> stretches_;  // by start; guarded by mutex_
};

}  // namespace

absl::StatusOr<std::vector<Hypothesis>> SeedHypotheses(const FacetMesh& fm, double tau,
                                                       const RunContext& ctx) {
  Walk walk(fm, tau);
  return walk.Run(ctx);
}

}  // namespace meshseg::segment_internal
