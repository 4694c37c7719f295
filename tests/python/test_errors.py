"""Bad input to glint.Structure raises glint.Error with glint's one-line message naming the argument,
and leaves an existing structure as it was."""
import numpy as np
import pytest

import glint
from conftest import random_rays, random_triangles


@pytest.fixture
def mesh(rng):
    return random_triangles(rng, count=20)


def raises(match):
    return pytest.raises(glint.Error, match=match)


def test_error_is_a_runtime_error():
    assert issubclass(glint.Error, RuntimeError)


@pytest.mark.parametrize("bad,match", [
    (lambda v: v.astype(np.int32), r"vertices: expected a float32 or float64 array of shape \(N, 3\), got a int32"),
    (lambda v: v[:, :2], r"vertices: expected .* got a float32 array of shape \(60, 2\)"),
    (lambda v: v.reshape(-1), r"vertices: expected .* shape \(180,\)"),
    (lambda v: v.astype(np.float16), r"vertices: expected a float32 or float64"),
])
def test_bad_vertices(mesh, bad, match):
    vertices, indices = mesh
    with raises(match):
        glint.Structure(bad(vertices), indices)


def test_not_an_array(mesh):
    _, indices = mesh
    with raises(r"^glint.Structure: vertices: expected an array, got list$"):
        glint.Structure([[0.0, 1.0, 2.0], [1.0]], indices)
    with raises(r"vertices: expected a float32 or float64 array of shape \(N, 3\), got a <U3 array of shape \(\)"):
        glint.Structure("abc", indices)


def test_nan_vertex(mesh):
    vertices, indices = mesh
    vertices[7, 1] = np.nan
    with raises(r"^glint.Structure: vertices: row 7 is not finite"):
        glint.Structure(vertices, indices)


@pytest.mark.parametrize("bad,match", [
    (lambda i: i.astype(np.float32), r"indices: expected an integer array of shape \(M, 3\)"),
    (lambda i: i.reshape(-1), r"indices: expected an integer array"),
    (lambda i: np.where(i == 5, 60, i), r"indices: triangle 1 uses vertex 60, but there are 60 vertices"),
    (lambda i: np.where(i == 4, -1, i.astype(np.int64)), r"indices: triangle 1 uses vertex -1"),
])
def test_bad_indices(mesh, bad, match):
    vertices, indices = mesh
    with raises(match):
        glint.Structure(vertices, bad(indices))


def test_no_triangles(mesh):
    vertices, _ = mesh
    with raises(r"^glint.Structure: the scene is empty"):
        glint.Structure(vertices, np.zeros((0, 3), dtype=np.uint32))


def test_unknown_builder_and_backend(mesh):
    vertices, indices = mesh
    with raises(r'unknown acceleration structure "bvh9" \(known: none, median, sah, sbvh, lbvh, trbvh, ploc, kdtree\)'):
        glint.Structure(vertices, indices, builder="bvh9")
    with raises(r"^glint.Structure: unknown backend \"gpu\" \(known: cpu, embree, cuda, optix\)$"):
        glint.Structure(vertices, indices, backend="gpu")
    with raises(r"builder=\"lbvh\" applies to the cpu and cuda backends"):
        glint.Structure(vertices, indices, builder="lbvh", backend="embree")


@pytest.mark.parametrize("change,match", [
    (dict(origins=lambda o: o.astype(np.int64)), r"trace_closest: origins: expected a float32 or float64"),
    (dict(directions=lambda d: d[:-1]), r"trace_closest: 10 origins but 9 directions"),
    (dict(origins=lambda o: np.where(o == o[3, 2], np.nan, o)), r"trace_closest: origins: row 3 is not finite"),
    (dict(directions=lambda d: np.where(np.arange(10)[:, None] == 4, 0.0, d).astype(np.float32)),
     r"trace_closest: direction 4 is zero"),
    (dict(t_min=np.nan), r"trace_closest: t_min of ray 0 is NaN"),
    (dict(t_max=np.zeros(3)), r"trace_closest: t_max must be a number or an array of 10 numbers"),
])
def test_bad_rays(mesh, rng, change, match):
    structure = glint.Structure(*mesh)
    origins, directions = random_rays(rng, count=10)
    args = dict(origins=origins, directions=directions)
    for name, value in change.items():
        if name in args:
            args[name] = value(args[name])
        else:
            args[name] = value
    with raises(match):
        structure.trace_closest(**args)
    with raises(match.replace("trace_closest", "trace_any")):
        structure.trace_any(**args)


def test_failed_refit_keeps_the_structure(mesh, rng):
    vertices, indices = mesh
    origins, directions = random_rays(rng, count=50)
    structure = glint.Structure(vertices, indices)
    before = structure.trace_closest(origins, directions)
    with raises(r"refit needs the same number of vertices as the structure was built with \(60\), got 59"):
        structure.refit(vertices[:-1])
    bad = vertices.copy()
    bad[3] = np.inf
    with raises(r"refit: vertices: row 3 is not finite"):
        structure.refit(bad)
    with raises(r"unknown update policy \"later\""):
        structure.refit(vertices, policy="later")
    after = structure.trace_closest(origins, directions)
    np.testing.assert_array_equal(after["prim"], before["prim"])
    np.testing.assert_array_equal(after["t"], before["t"])


@pytest.mark.parametrize("builder", ["sbvh", "kdtree"])
def test_unrefittable_structures_say_so_and_rebuild(mesh, builder):
    vertices, indices = mesh
    structure = glint.Structure(vertices, indices, builder=builder)
    with pytest.raises(glint.Error, match="refit") as raised:
        structure.refit(vertices)
    assert "\n" not in str(raised.value)
    structure.refit(vertices, policy="rebuild")  # rebuilding is always possible
