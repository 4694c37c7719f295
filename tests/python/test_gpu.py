"""The cuda backend from Python. Without a CUDA GPU (or in a build without CUDA) asking for it is one
clear glint.Error; with one, its hits equal the brute force like the CPU backends' (these tests skip
without a GPU: the GPU machine runs them)."""
import numpy as np
import pytest

import glint
from conftest import assert_hits_match, brute_force_closest, random_rays, random_triangles

needs_gpu = pytest.mark.skipif(not glint.cuda_available(), reason="needs a CUDA GPU")


@pytest.mark.skipif(glint.cuda_available(), reason="this machine has a CUDA GPU")
@pytest.mark.parametrize("backend", ["cuda", "optix"])
def test_gpu_backend_without_gpu_is_one_clear_error(rng, backend):
    vertices, indices = random_triangles(rng, count=10)
    with pytest.raises(glint.Error, match=f"needs a CUDA GPU|built without CUDA|not in this build") as raised:
        glint.Structure(vertices, indices, backend=backend)
    assert "\n" not in str(raised.value)


@needs_gpu
@pytest.mark.parametrize("builder", glint.BUILDERS)
def test_cuda_hits_equal_brute_force(rng, builder):
    vertices, indices = random_triangles(rng)
    origins, directions = random_rays(rng)
    structure = glint.Structure(vertices, indices, builder=builder, backend="cuda")
    hits = structure.trace_closest(origins, directions)
    assert_hits_match(hits, brute_force_closest(vertices, indices, origins, directions))
    np.testing.assert_array_equal(structure.trace_any(origins, directions), hits["prim"] >= 0)


@needs_gpu
@pytest.mark.parametrize("builder", ["lbvh", "ploc", "sah"])
def test_cuda_refit(rng, builder):
    vertices, indices = random_triangles(rng)
    origins, directions = random_rays(rng)
    structure = glint.Structure(vertices, indices, builder=builder, backend="cuda")
    new_vertices = (vertices + 0.2 * np.sin(3.0 * vertices[:, [0]])).astype(np.float32)
    structure.refit(new_vertices)
    assert_hits_match(structure.trace_closest(origins, directions),
                      brute_force_closest(new_vertices, indices, origins, directions))


@needs_gpu
def test_optix_hits_equal_brute_force(rng):
    vertices, indices = random_triangles(rng)
    origins, directions = random_rays(rng)
    try:
        structure = glint.Structure(vertices, indices, backend="optix")
    except glint.Error as error:
        if "not in this build" in str(error):
            pytest.skip(str(error))
        raise
    hits = structure.trace_closest(origins, directions)
    assert_hits_match(hits, brute_force_closest(vertices, indices, origins, directions))
    np.testing.assert_array_equal(structure.trace_any(origins, directions), hits["prim"] >= 0)
