#include "fit/levenberg_marquardt.h"

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace meshseg::fit_internal {
namespace {

// y = a exp(b t) through points (t_i, y_i) stored as (t, y, 0).
class ExponentialProblem : public LeastSquaresProblem {
 public:
  explicit ExponentialProblem(const FitInput& input) : input_(input) {}
  int NumSteps() const override { return 2; }
  double Evaluate(const Eigen::VectorXd& x, Eigen::MatrixXd* jtj,
                  Eigen::VectorXd* jtr) const override {
    return AccumulateNormalEquations<2>(
        input_,
        [&](std::size_t i, Eigen::Matrix<double, 1, 2>* row) {
          const double t = input_.points[i].x();
          const double e = std::exp(x(1) * t);
          *row << e, x(0) * t * e;
          return x(0) * e - input_.points[i].y();
        },
        jtj, jtr);
  }
  Eigen::VectorXd Step(const Eigen::VectorXd& x, const Eigen::VectorXd& step) const override {
    return x + step;
  }

 private:
  const FitInput& input_;
};

std::vector<Eigen::Vector3d> Samples() {
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i <= 20; ++i) {
    const double t = 0.1 * i;
    pts.emplace_back(t, 2.0 * std::exp(-1.5 * t), 0.0);
  }
  return pts;
}

TEST(MinimizeLevenbergMarquardt, ConvergesFromFarStart) {
  const auto pts = Samples();
  const FitInput input{pts, {}, {}};
  const LmOutcome out =
      MinimizeLevenbergMarquardt(ExponentialProblem(input), Eigen::Vector2d(0.5, 1.0), FitParams{});
  EXPECT_TRUE(out.converged);
  EXPECT_NEAR(out.x(0), 2.0, 1e-8);
  EXPECT_NEAR(out.x(1), -1.5, 1e-8);
  EXPECT_LT(out.cost, 1e-16);
  EXPECT_GT(out.initial_cost, out.cost);
}

TEST(MinimizeLevenbergMarquardt, RespectsIterationLimit) {
  const auto pts = Samples();
  const FitInput input{pts, {}, {}};
  const LmOutcome out = MinimizeLevenbergMarquardt(
      ExponentialProblem(input), Eigen::Vector2d(0.5, 1.0), FitParams{.max_iterations = 2});
  EXPECT_LE(out.iterations, 2);
  EXPECT_LE(out.cost, out.initial_cost);
}

TEST(MinimizeLevenbergMarquardt, WeightsScaleTheCost) {
  const auto pts = Samples();
  const std::vector<double> w(pts.size(), 4.0);
  const Eigen::Vector2d x0(1.0, -1.0);
  const double plain =
      MinimizeLevenbergMarquardt(ExponentialProblem(FitInput{pts, {}, {}}), x0,
                                 FitParams{.max_iterations = 0})
          .cost;
  const double weighted =
      MinimizeLevenbergMarquardt(ExponentialProblem(FitInput{pts, {}, w}), x0,
                                 FitParams{.max_iterations = 0})
          .cost;
  EXPECT_NEAR(weighted, 4.0 * plain, 1e-12 * weighted);
}

TEST(MinimizeLevenbergMarquardt, ExactStartStopsAtOnce) {
  const auto pts = Samples();
  const FitInput input{pts, {}, {}};
  const LmOutcome out =
      MinimizeLevenbergMarquardt(ExponentialProblem(input), Eigen::Vector2d(2.0, -1.5), FitParams{});
  EXPECT_TRUE(out.converged);
  EXPECT_LE(out.iterations, 1);
}

// y = sum_k c_k t^k, k < P, through points (t_i, y_i) stored as (t, y, 0):
// linear in c, so the damped steps reach the coefficients in a few
// iterations. P = 5 and 6 take the fixed-size step solve (the axial fits'
// step counts), P = 7 the dynamic one.
template <int P>
class PolynomialProblem : public LeastSquaresProblem {
 public:
  explicit PolynomialProblem(const FitInput& input) : input_(input) {}
  int NumSteps() const override { return P; }
  double Evaluate(const Eigen::VectorXd& x, Eigen::MatrixXd* jtj,
                  Eigen::VectorXd* jtr) const override {
    return AccumulateNormalEquations<P>(
        input_,
        [&](std::size_t i, Eigen::Matrix<double, 1, P>* row) {
          const double t = input_.points[i].x();
          double power = 1.0, y = 0.0;
          for (int k = 0; k < P; ++k, power *= t) {
            (*row)(k) = power;
            y += x(k) * power;
          }
          return y - input_.points[i].y();
        },
        jtj, jtr);
  }
  Eigen::VectorXd Step(const Eigen::VectorXd& x, const Eigen::VectorXd& step) const override {
    return x + step;
  }

 private:
  const FitInput& input_;
};

template <int P>
void ExpectPolynomialFound() {
  Eigen::VectorXd truth(P);
  for (int k = 0; k < P; ++k) truth(k) = (k % 2 ? -1.0 : 1.0) * (k + 1);
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i <= 30; ++i) {
    const double t = -1.0 + i / 15.0;
    double y = 0.0;
    for (int k = P - 1; k >= 0; --k) y = y * t + truth(k);
    pts.emplace_back(t, y, 0.0);
  }
  const FitInput input{pts, {}, {}};
  const LmOutcome out = MinimizeLevenbergMarquardt(PolynomialProblem<P>(input),
                                                   Eigen::VectorXd::Zero(P), FitParams{});
  EXPECT_LT(out.cost, 1e-20) << P << " coefficients";
  for (int k = 0; k < P; ++k) EXPECT_NEAR(out.x(k), truth(k), 1e-9) << P << " coefficients";
}

TEST(MinimizeLevenbergMarquardt, FindsFiveSixAndSevenCoefficients) {
  ExpectPolynomialFound<5>();
  ExpectPolynomialFound<6>();
  ExpectPolynomialFound<7>();
}

// The normal equations summed over the lower triangle only are those of the
// full outer product w row^T row, bit for bit: every entry is the same sum
// of the same products in the same order (the fits' results must not move
// by a rounding). Rows from a fixed pseudo-random draw of widely scaled
// values, so a product taken in another order would differ in its last bits.
template <int P>
void ExpectLowerTriangleIsTheFullProduct() {
  std::mt19937 random(17 + P);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::vector<Eigen::Matrix<double, 1, P>> rows(257);
  std::vector<Eigen::Vector3d> pts(rows.size());
  std::vector<double> weights(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    for (int k = 0; k < P; ++k) rows[i](k) = value(random) * std::exp(6.0 * value(random));
    pts[i] = Eigen::Vector3d(value(random), 0.0, 0.0);  // x: the residual
    weights[i] = 0.5 + value(random) * value(random);
  }
  const FitInput input{pts, {}, weights};
  Eigen::MatrixXd jtj;
  Eigen::VectorXd jtr;
  const double cost = AccumulateNormalEquations<P>(
      input,
      [&](std::size_t i, Eigen::Matrix<double, 1, P>* row) {
        *row = rows[i];
        return pts[i].x();
      },
      &jtj, &jtr);
  Eigen::Matrix<double, P, P> a = Eigen::Matrix<double, P, P>::Zero();
  Eigen::Matrix<double, P, 1> b = Eigen::Matrix<double, P, 1>::Zero();
  double sum = 0.0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double w = weights[i], r = pts[i].x();
    sum += w * r * r;
    a.noalias() += w * rows[i].transpose() * rows[i];
    b.noalias() += (w * r) * rows[i].transpose();
  }
  ASSERT_EQ(jtj.rows(), P);
  ASSERT_EQ(jtj.cols(), P);
  ASSERT_EQ(jtr.size(), P);
  EXPECT_EQ(std::memcmp(&cost, &sum, sizeof cost), 0) << cost << " vs " << sum;
  for (int k = 0; k < P; ++k) {
    EXPECT_EQ(std::memcmp(&jtr(k), &b(k), sizeof(double)), 0) << P << ": b " << k;
    for (int l = 0; l <= k; ++l) {
      EXPECT_EQ(std::memcmp(&jtj(k, l), &a(k, l), sizeof(double)), 0)
          << P << ": (" << k << ", " << l << ") " << jtj(k, l) << " vs " << a(k, l);
      EXPECT_EQ(jtj(l, k), jtj(k, l)) << P << ": symmetric";
    }
  }
}

TEST(AccumulateNormalEquations, LowerTriangleIsTheFullProductBitForBit) {
  ExpectLowerTriangleIsTheFullProduct<4>();
  ExpectLowerTriangleIsTheFullProduct<5>();
  ExpectLowerTriangleIsTheFullProduct<6>();
  ExpectLowerTriangleIsTheFullProduct<7>();
}

}  // namespace
}  // namespace meshseg::fit_internal
