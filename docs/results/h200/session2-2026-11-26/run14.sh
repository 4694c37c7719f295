#!/usr/bin/env bash
# Run 14 of 2026-11-26 (session 2): the many-sample frame test and the GPU frame-loop, glossy and cuda tests after the time-ring fix.
set -u
mkdir -p /tmp/w && tar -xJf .gpu.tar.xz -C /tmp/w && source /tmp/w/.gpu/env.sh
export GLINT_CLI=/tmp/w/.gpu/bin/glint GLINT_SOURCE_DIR=$PWD
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader; date -u
timeout 300 glint_tests --gtest_brief=1 --gtest_filter='*RenderManySamples*:*FrameLoop*:*Glossy*:*RenderScopesCli*:*Cuda*:*Optix*:*Denoiser*' 2>&1 | grep -E "FAILED|PASSED|SKIPPED \]|tests from|Failure" | head
