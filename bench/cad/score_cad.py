#!/usr/bin/env python3
"""Scores a meshseg result JSON against per-triangle B-rep face labels.

usage: score_cad.py MESH.obj LABELS.txt FEATURES.yml RESULT.json [--time S]
       (LABELS.txt may be "-": the face_indices of FEATURES.yml give the labels)

Truth: face k of FEATURES.yml (ABC "feat" style: type, location, z_axis,
radius, angle, apex, max_radius/min_radius). Faces whose surfaces coincide
(same type; axes, offsets and radii equal within 1e-6 of the bounding-box
diagonal D) are one truth surface ("patches merged by shared surface").
Prints one row: faces, regions, area right %, faces (>= 20 triangles)
found with their type, worst parameter error (relative to D; angles in
radians), shared surfaces reported once.
"""
import json, math, sys
import yaml

REL = 1e-6
MIN_TRIANGLES = 20


def read_obj(path):
    v, f = [], []
    with open(path) as fh:
        for line in fh:
            if line.startswith('v '):
                v.append(tuple(map(float, line.split()[1:4])))
            elif line.startswith('f '):
                f.append(tuple(int(t.split('/')[0]) - 1 for t in line.split()[1:4]))
    return v, f


def sub(a, b): return (a[0]-b[0], a[1]-b[1], a[2]-b[2])
def dot(a, b): return a[0]*b[0]+a[1]*b[1]+a[2]*b[2]
def cross(a, b): return (a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0])
def norm(a): return math.sqrt(dot(a, a))
def unit(a):
    n = norm(a)
    return (a[0]/n, a[1]/n, a[2]/n) if n > 0 else a
def axis_angle(a, b):
    a, b = unit(a), unit(b)
    return math.atan2(norm(cross(a, b)), abs(dot(a, b)))
def line_distance(p, q, d):
    d = unit(d)
    w = sub(p, q)
    return norm(sub(w, tuple(dot(w, d)*x for x in d)))


def truth_surface(s):
    t = s['type']
    out = {'type': t}
    if t == 'Plane':
        out.update(point=tuple(s['location']), normal=tuple(s['z_axis']))
    elif t == 'Cylinder':
        out.update(point=tuple(s['location']), axis=tuple(s['z_axis']), radius=s['radius'])
    elif t == 'Cone':
        out.update(apex=tuple(s['apex']), axis=tuple(s['z_axis']), angle=s['angle'])
    elif t == 'Sphere':
        out.update(center=tuple(s['location']), radius=s['radius'])
    elif t == 'Torus':
        out.update(center=tuple(s['location']), axis=tuple(s['z_axis']),
                   major=s['max_radius'], minor=s['min_radius'])
    return out


def result_surface(r):
    t = r['type'].replace('SURFACE_TYPE_', '').capitalize()
    v = lambda d: (d.get('x', 0.0), d.get('y', 0.0), d.get('z', 0.0))
    out = {'type': t}
    if 'plane' in r:
        out.update(point=v(r['plane']['point']), normal=v(r['plane']['normal']))
    elif 'cylinder' in r:
        c = r['cylinder']; out.update(point=v(c['axis_origin']), axis=v(c['axis_direction']), radius=c['radius'])
    elif 'cone' in r:
        c = r['cone']; out.update(apex=v(c['apex']), axis=v(c['axis_direction']), angle=c['half_angle'])
    elif 'sphere' in r:
        c = r['sphere']; out.update(center=v(c['center']), radius=c['radius'])
    elif 'torus' in r:
        c = r['torus']; out.update(center=v(c['center']), axis=v(c['axis_direction']),
                                   major=c['major_radius'], minor=c['minor_radius'])
    return out


def error(a, b, D):
    """Worst parameter difference of two surfaces of one type, relative to D."""
    t = a['type']
    if t != b['type']:
        return math.inf
    if t == 'Plane':
        return max(axis_angle(a['normal'], b['normal']),
                   abs(dot(sub(b['point'], a['point']), unit(a['normal']))) / D)
    if t == 'Cylinder':
        return max(axis_angle(a['axis'], b['axis']), line_distance(b['point'], a['point'], a['axis']) / D,
                   abs(a['radius'] - b['radius']) / D)
    if t == 'Cone':
        return max(axis_angle(a['axis'], b['axis']), norm(sub(a['apex'], b['apex'])) / D,
                   abs(a['angle'] - b['angle']))
    if t == 'Sphere':
        return max(norm(sub(a['center'], b['center'])) / D, abs(a['radius'] - b['radius']) / D)
    if t == 'Torus':
        return max(axis_angle(a['axis'], b['axis']), norm(sub(a['center'], b['center'])) / D,
                   abs(a['major'] - b['major']) / D, abs(a['minor'] - b['minor']) / D)
    return math.inf


def main():
    mesh, labels_path, yml, result_path = sys.argv[1:5]
    seconds = float(sys.argv[sys.argv.index('--time') + 1]) if '--time' in sys.argv else float('nan')
    v, f = read_obj(mesh)
    with open(yml) as fh:
        text = fh.read()
    loader = getattr(yaml, 'CSafeLoader', yaml.SafeLoader)
    doc = yaml.load(text, Loader=loader)
    surfaces = doc['surfaces']
    if labels_path == '-':
        labels = [-1] * len(f)
        for k, s in enumerate(surfaces):
            for i in s.get('face_indices', []):
                labels[i] = k
    else:
        labels = [int(x) for x in open(labels_path).read().split() if x.strip().lstrip('-').isdigit()]
    assert len(labels) == len(f), (len(labels), len(f))
    lo = [min(p[k] for p in v) for k in range(3)]
    hi = [max(p[k] for p in v) for k in range(3)]
    D = norm(sub(hi, lo))
    area = [0.5 * norm(cross(sub(v[b], v[a]), sub(v[c], v[a]))) for a, b, c in f]
    truth = [truth_surface(s) for s in surfaces]
    # Truth faces merged by shared surface.
    group = list(range(len(truth)))
    for i in range(len(truth)):
        for j in range(i):
            if group[j] == j and truth[i]['type'] != 'BSpline' and error(truth[i], truth[j], D) < REL:
                group[i] = j
                break
    with open(result_path) as fh:
        res = json.load(fh)
    face_labels = res['face_labels']
    regions = res['regions']
    # Majority truth surface (by area) of each region.
    votes = {}
    for i, r in enumerate(face_labels):
        if labels[i] < 0:
            continue
        key = (r, group[labels[i]])
        votes[key] = votes.get(key, 0.0) + area[i]
    majority = {}
    for (r, g), a in votes.items():
        if r not in majority or a > majority[r][1]:
            majority[r] = (g, a)
    right = sum(area[i] for i, r in enumerate(face_labels)
                if labels[i] >= 0 and r in majority and majority[r][0] == group[labels[i]])
    total = sum(area[i] for i in range(len(f)) if labels[i] >= 0)
    # Faces of >= MIN_TRIANGLES: the region holding most of their area.
    faces_big, found, worst, misses = 0, 0, 0.0, []
    for k in range(len(truth)):
        tri = [i for i in range(len(f)) if labels[i] == k]
        if len(tri) < MIN_TRIANGLES:
            continue
        faces_big += 1
        share = {}
        for i in tri:
            share[face_labels[i]] = share.get(face_labels[i], 0.0) + area[i]
        r = max(share, key=share.get)
        got = result_surface(regions[r]) if 0 <= r < len(regions) else {'type': 'none'}
        e = error(truth[k], got, D) if truth[k]['type'] != 'BSpline' else (0.0 if got['type'] == 'Freeform' else math.inf)
        if got['type'] == truth[k]['type'] or (truth[k]['type'] == 'BSpline' and got['type'] == 'Freeform'):
            found += 1
            worst = max(worst, e)
        else:
            misses.append('%d:%s->%s' % (k, truth[k]['type'], got['type']))
    # Shared surfaces reported once: truth surfaces of >= 2 faces whose regions share one surface_id.
    shared_groups = {}
    for k in range(len(truth)):
        shared_groups.setdefault(group[k], []).append(k)
    shared_total, shared_once = 0, 0
    for g, members in shared_groups.items():
        if len(members) < 2:
            continue
        regs = set()
        for i in range(len(f)):
            if labels[i] in members:
                regs.add(face_labels[i])
        if len(regs) < 2:
            continue  # one region holds them all
        shared_total += 1
        ids = set(regions[r].get('surface_id', r) for r in regs if 0 <= r < len(regions))
        shared_once += len(ids) == 1
    types = {}
    for r in regions:
        t = r['type'].replace('SURFACE_TYPE_', '').lower()
        types[t] = types.get(t, 0) + 1
    est = res.get('estimates', {})
    path = est.get('segmentation_path', 'remesh' if est.get('remesh_face_count', 0) else 'scan')
    print('%-58s F %6d faces %3d regions %4d (%.2fx) area %6.2f%% found %3d/%-3d worst %.1e shared %d/%d time %.2fs path %s types %s%s' % (
        mesh.split('/')[-1][:58], len(f), len(truth), len(regions), len(regions) / max(1, len(truth)),
        100.0 * right / total, found, faces_big, worst, shared_once, shared_total, seconds, path,
        ' '.join('%s:%d' % kv for kv in sorted(types.items())),
        ('  miss ' + ' '.join(misses[:8])) if misses else ''))


if __name__ == '__main__':
    main()
