// The viewer's walkthrough clock: it advances at the walkthrough's frame rate times the speed while
// playing, wraps at the end, stands still when paused, and flying does not stop it (the flown camera
// sees the frames as they play).
#include "viewer/playback.h"

#include <gtest/gtest.h>

namespace glint::viewer {
namespace {

TEST(ViewerPlayback, AdvancesWhilePlayingEvenWhenFlying) {
  ViewerState state;
  state.frame = 10.0;
  state.playing = true;
  state.speed = 2.0f;
  advance_playback(state, 0.5f, 30.0f, 100);
  EXPECT_DOUBLE_EQ(state.frame, 40.0);
  state.flying = true;
  advance_playback(state, 0.5f, 30.0f, 100);
  EXPECT_DOUBLE_EQ(state.frame, 70.0) << "flying keeps the walkthrough's clock running";
  advance_playback(state, 0.5f, 30.0f, 100);
  EXPECT_DOUBLE_EQ(state.frame, 0.0) << "wraps at the end";
  state.playing = false;
  advance_playback(state, 0.5f, 30.0f, 100);
  EXPECT_DOUBLE_EQ(state.frame, 0.0);
}

}  // namespace
}  // namespace glint::viewer
