#pragma once
// Which frames of a walkthrough to render (`glint render --frames`, `glint compare --frames`).
//
// Grammar: a comma-separated list of items, each one of
//   N          the single frame N
//   A:B        frames A to B, both included
//   A:B:step   A, A+step, ... up to at most B
// for example "1800,2100,2300,4400" (the paper's comparison frames), "0:4899:10" or "0:10:5,100".
// Spaces around items and numbers are allowed. Frames count from 0.
//
// Parsing checks the text alone (numbers, negative values, B < A, step <= 0); resolve() checks it
// against the walkthrough's frame count, which the command learns only after loading the scene. Each
// error is one line that quotes the whole text and the offending item.
#include <string>
#include <string_view>
#include <vector>

namespace glint {

class FrameSelection {
public:
  // Throws a glint::Error for text that is not a valid selection.
  static FrameSelection parse(std::string_view text);
  // Every frame of the walkthrough (what a command does when no selection is given).
  static FrameSelection all();

  // The selected frames, ascending, each once (a frame named twice is rendered once). A frame past
  // the walkthrough's last one, or a walkthrough without frames, is a glint::Error, e.g.
  //   frame selection "4000:5000": frame 5000 (in "4000:5000") is past the walkthrough's last frame 4899
  std::vector<int> resolve(int frame_count) const;

  const std::string& text() const { return text_; }

private:
  struct Item {
    int first = 0;
    int last = 0;  // the last frame the item selects (for A:B:step, A + k*step <= B)
    int step = 1;
    std::string text;  // as written, for messages
  };

  std::string text_;
  std::vector<Item> items_;
  bool all_ = false;
};

}  // namespace glint
