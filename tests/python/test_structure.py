"""glint.Structure on the CPU backends: every builder's closest hits equal a brute-force
Möller–Trumbore over numpy triangles, trace_any agrees with them, refit follows moved vertices."""
import numpy as np
import pytest

import glint
from conftest import assert_hits_match, brute_force_closest, random_rays, random_triangles

CPU_CASES = [("cpu", builder) for builder in glint.BUILDERS] + [("embree", "sah")]


def test_builders_and_backends_are_listed():
    assert set(glint.BUILDERS) == {"none", "median", "sah", "sbvh", "lbvh", "trbvh", "ploc", "kdtree"}
    assert glint.BACKENDS == ("cpu", "embree", "cuda", "optix")


@pytest.mark.parametrize("backend,builder", CPU_CASES)
def test_closest_hits_equal_brute_force(rng, backend, builder):
    vertices, indices = random_triangles(rng)
    origins, directions = random_rays(rng)
    structure = glint.Structure(vertices, indices, builder=builder, backend=backend)
    assert (structure.backend, structure.builder) == (backend, builder)
    assert (structure.vertex_count, structure.triangle_count) == (len(vertices), len(indices))
    hits = structure.trace_closest(origins, directions)
    assert_hits_match(hits, brute_force_closest(vertices, indices, origins, directions))
    # u, v are the hit's barycentrics: they rebuild the point origin + t * direction.
    found = hits["prim"] >= 0
    tri = vertices[indices[hits["prim"][found]]].astype(np.float64)
    u, v = hits["u"][found, None], hits["v"][found, None]
    point = (1 - u - v) * tri[:, 0] + u * tri[:, 1] + v * tri[:, 2]
    expected = origins[found] + hits["t"][found, None] * directions[found]
    assert np.abs(point - expected).max() < 1e-4


@pytest.mark.parametrize("backend,builder", CPU_CASES)
def test_closest_hits_equal_cpp_brute_force(rng, backend, builder):
    # builder "none" tests every triangle (glint's C++ brute force); the same watertight test in every
    # structure finds the same triangle at the same t, to the bit.
    vertices, indices = random_triangles(rng)
    origins, directions = random_rays(rng)
    reference = glint.Structure(vertices, indices, builder="none").trace_closest(origins, directions)
    hits = glint.Structure(vertices, indices, builder=builder, backend=backend).trace_closest(origins, directions)
    np.testing.assert_array_equal(hits["prim"], reference["prim"])
    if backend == "cpu":
        for key in ("t", "u", "v"):
            np.testing.assert_array_equal(hits[key], reference[key])
    else:  # Embree has its own triangle test
        np.testing.assert_allclose(hits["t"], reference["t"], rtol=1e-5)


@pytest.mark.parametrize("backend,builder", CPU_CASES)
def test_ray_interval_limits_hits(rng, backend, builder):
    vertices, indices = random_triangles(rng)
    origins, directions = random_rays(rng)
    t_min = rng.uniform(0.0, 0.4, len(origins))
    t_max = 0.7  # one number for every ray
    structure = glint.Structure(vertices, indices, builder=builder, backend=backend)
    hits = structure.trace_closest(origins, directions, t_min=t_min, t_max=t_max)
    assert_hits_match(hits, brute_force_closest(vertices, indices, origins, directions, t_min, t_max))


@pytest.mark.parametrize("backend,builder", CPU_CASES)
def test_trace_any_agrees_with_closest(rng, backend, builder):
    vertices, indices = random_triangles(rng)
    origins, directions = random_rays(rng)
    structure = glint.Structure(vertices, indices, builder=builder, backend=backend)
    for t_max in (np.inf, 0.6):
        closest = structure.trace_closest(origins, directions, t_max=t_max)
        occluded = structure.trace_any(origins, directions, t_max=t_max)
        assert occluded.dtype == np.bool_ and occluded.shape == (len(origins),)
        np.testing.assert_array_equal(occluded, closest["prim"] >= 0)
        assert 0 < occluded.sum() < len(origins)


def moved(vertices, rng):
    """Every vertex moved by up to 0.3 along a wave plus noise: hits change, topology does not."""
    wave = 0.3 * np.sin(3.0 * vertices[:, [0]]) * np.array([[0.0, 1.0, 0.5]])
    return (vertices + wave + rng.uniform(-0.05, 0.05, vertices.shape)).astype(np.float32)


@pytest.mark.parametrize("backend,builder", [c for c in CPU_CASES if c[1] not in ("sbvh", "kdtree")])
def test_refit_follows_moved_vertices(rng, backend, builder):
    vertices, indices = random_triangles(rng)
    origins, directions = random_rays(rng)
    structure = glint.Structure(vertices, indices, builder=builder, backend=backend)
    before = structure.trace_closest(origins, directions)
    new_vertices = moved(vertices, rng)
    structure.refit(new_vertices)
    after = structure.trace_closest(origins, directions)
    assert_hits_match(after, brute_force_closest(new_vertices, indices, origins, directions))
    assert (after["prim"] != before["prim"]).sum() > 10  # the motion changed the answers
    stats = structure.stats()
    if backend == "cpu":
        assert stats["refits"] == 1 and stats["rebuilds"] == 0


@pytest.mark.parametrize("policy", ["rebuild", "auto"])
def test_refit_policies(rng, policy):
    vertices, indices = random_triangles(rng)
    origins, directions = random_rays(rng)
    structure = glint.Structure(vertices, indices, builder="sbvh" if policy == "rebuild" else "sah")
    new_vertices = moved(vertices, rng)
    structure.refit(new_vertices, policy=policy)
    assert_hits_match(structure.trace_closest(origins, directions),
                      brute_force_closest(new_vertices, indices, origins, directions))
    if policy == "rebuild":
        assert structure.stats()["rebuilds"] == 1


def test_stats(rng):
    vertices, indices = random_triangles(rng)
    stats = glint.Structure(vertices, indices, builder="trbvh").stats()
    assert stats["backend"] == "cpu" and stats["builder"] == "trbvh"
    assert stats["vertices"] == len(vertices) and stats["triangles"] == len(indices)
    assert stats["build_ms"] > 0 and stats["memory_bytes"] > len(indices) * 36
    assert stats["refits"] == 0 and stats["rebuilds"] == 0
    assert stats["sah_drift"] == pytest.approx(1.0)


def test_shared_vertices_and_index_dtypes(rng):
    # A quad of two triangles sharing an edge, int64 indices (numpy's default) and float64 vertices.
    vertices = np.array([[-1, -1, 2], [1, -1, 2], [1, 1, 2], [-1, 1, 2]], dtype=np.float64)
    indices = np.array([[0, 1, 2], [0, 2, 3]])
    structure = glint.Structure(vertices, indices)
    origins = np.zeros((3, 3), dtype=np.float32)
    directions = np.array([[0.5, -0.2, 2], [-0.5, 0.2, 2], [0, 0, -1]], dtype=np.float32)
    hits = structure.trace_closest(origins, directions)
    np.testing.assert_array_equal(hits["prim"], [0, 1, -1])
    np.testing.assert_allclose(hits["t"][:2], [1.0, 1.0], rtol=1e-6)
    assert hits["t"][2] == np.inf


def test_nested_lists_are_arrays():
    structure = glint.Structure([[0, 0, 1], [1, 0, 1], [0, 1, 1.0]], [[0, 1, 2]])
    hits = structure.trace_closest([[0.25, 0.25, 0.0]], [[0.0, 0.0, 2.0]])
    assert hits["prim"].tolist() == [0] and hits["t"].tolist() == [0.5]
    assert structure.trace_any([[0.25, 0.25, 0.0]], [[0.0, 0.0, 2.0]], t_max=[0.4]).tolist() == [False]


def test_no_rays(rng):
    vertices, indices = random_triangles(rng, count=10)
    structure = glint.Structure(vertices, indices)
    empty = np.zeros((0, 3), dtype=np.float32)
    assert structure.trace_closest(empty, empty)["t"].shape == (0,)
    assert structure.trace_any(empty, empty).shape == (0,)
