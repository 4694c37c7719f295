"""Shared pieces of the Python tests: random triangles and rays, and the brute-force reference.

The module under test is the `glint` built into <build>/python (CTest sets PYTHONPATH), run with
Debian's /usr/bin/python3 and its numpy and pytest (scripts/setup.sh).
"""
import numpy as np
import pytest


def random_triangles(rng, count=300, size=0.35):
    """`count` triangles of about `size` scattered in [-1, 1]^3: float32 vertices (3*count, 3) and
    uint32 indices (count, 3), each triangle on its own three vertices."""
    centres = rng.uniform(-1.0, 1.0, (count, 1, 3))
    corners = centres + rng.uniform(-size, size, (count, 3, 3))
    vertices = corners.reshape(-1, 3).astype(np.float32)
    indices = np.arange(3 * count, dtype=np.uint32).reshape(count, 3)
    return vertices, indices


def random_rays(rng, count=400):
    """Rays from a sphere of radius 3 around the triangles: most aimed into [-1, 1]^3 (hits and some
    misses between the triangles), a quarter aimed away (misses). float32 origins and directions."""
    origins = rng.normal(size=(count, 3))
    origins = 3.0 * origins / np.linalg.norm(origins, axis=1, keepdims=True)
    targets = rng.uniform(-1.0, 1.0, (count, 3))
    directions = targets - origins
    away = rng.random(count) < 0.25
    directions[away] = -directions[away]
    return origins.astype(np.float32), directions.astype(np.float32)


def brute_force_closest(vertices, indices, origins, directions, t_min=0.0, t_max=np.inf):
    """Möller–Trumbore against every triangle, per ray, in float64: (t, prim, margin) with t = inf
    and prim = -1 for a miss; margin is how far inside its triangle the hit lies (the smallest
    barycentric), which says how close to an edge the answer is."""
    v = vertices.astype(np.float64)[indices.astype(np.int64)]  # (M, 3 corners, 3)
    v0, e1, e2 = v[:, 0], v[:, 1] - v[:, 0], v[:, 2] - v[:, 0]
    o = origins.astype(np.float64)[:, None, :]  # (R, 1, 3)
    d = directions.astype(np.float64)[:, None, :]
    p = np.cross(d, e2[None])  # (R, M, 3)
    det = np.einsum("rmk,mk->rm", p, e1)
    with np.errstate(divide="ignore", invalid="ignore"):
        inv = 1.0 / det
        s = o - v0[None]
        u = np.einsum("rmk,rmk->rm", s, p) * inv
        q = np.cross(s, e1[None])
        w = np.einsum("rmk,rk->rm", q, directions.astype(np.float64)) * inv
        t = np.einsum("rmk,mk->rm", q, e2) * inv
    margin = np.minimum(np.minimum(u, w), 1.0 - u - w)
    t_min = np.broadcast_to(np.asarray(t_min, dtype=np.float64), (len(origins),))[:, None]
    t_max = np.broadcast_to(np.asarray(t_max, dtype=np.float64), (len(origins),))[:, None]
    hit = (det != 0) & (margin >= 0) & (t >= t_min) & (t <= t_max)
    t_hit = np.where(hit, t, np.inf)
    prim = np.argmin(t_hit, axis=1)
    rows = np.arange(len(origins))
    best_t = t_hit[rows, prim]
    best_margin = np.where(np.isfinite(best_t), margin[rows, prim], np.inf)
    prim = np.where(np.isfinite(best_t), prim, -1)
    return best_t, prim, best_margin, t_hit, margin


def assert_hits_match(hits, reference, edge=1e-5, rel=1e-4):
    """glint's closest hits against the brute force: the same triangle and t, except where the
    reference itself is within `edge` (barycentric) of a triangle's border, where watertight and
    Möller–Trumbore tests may round to different sides, or where two triangles tie in t."""
    t_ref, prim_ref, margin_ref, t_all, margin_all = reference
    n = len(t_ref)
    assert hits["t"].shape == (n,) and hits["prim"].shape == (n,)
    assert hits["t"].dtype == np.float32 and hits["prim"].dtype == np.int64
    problems = []
    for i in range(n):
        prim, t = int(hits["prim"][i]), float(hits["t"][i])
        if prim == prim_ref[i] and (prim < 0 or abs(t - t_ref[i]) <= rel * max(1.0, t_ref[i])):
            if prim < 0 and np.isfinite(t):
                problems.append(f"ray {i}: a miss with t = {t}")
            continue
        if prim < 0:  # glint missed what the reference hit: only at an edge
            if margin_ref[i] > edge:
                problems.append(f"ray {i}: missed triangle {prim_ref[i]} at t = {t_ref[i]}")
            continue
        # glint hit `prim`: it must be a real hit at that t and no farther than the reference's
        near_edge = abs(margin_all[i, prim]) <= edge
        if not (np.isfinite(t_all[i, prim]) or near_edge):
            problems.append(f"ray {i}: hit triangle {prim}, which the ray does not meet")
        elif np.isfinite(t_all[i, prim]) and abs(t - t_all[i, prim]) > rel * max(1.0, t):
            problems.append(f"ray {i}: t = {t} on triangle {prim}, reference {t_all[i, prim]}")
        elif t > t_ref[i] + rel * max(1.0, t_ref[i]) and margin_ref[i] > edge:
            problems.append(f"ray {i}: triangle {prim} at t = {t}, but {prim_ref[i]} is nearer at {t_ref[i]}")
    assert not problems, "\n".join(problems[:20])
    # Not vacuous: the rays both hit and miss, and nearly all agree exactly.
    assert (prim_ref >= 0).sum() > n // 5 and (prim_ref < 0).sum() > n // 10
    assert (hits["prim"] == prim_ref).mean() > 0.98


@pytest.fixture
def rng():
    return np.random.default_rng(20)
