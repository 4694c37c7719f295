#include "app/frame_selection.h"

#include "core/error.h"

#include <charconv>
#include <system_error>

namespace glint {
namespace {

std::string_view trimmed(std::string_view text) {
  const std::size_t begin = text.find_first_not_of(" \t");
  if (begin == std::string_view::npos) return {};
  const std::size_t end = text.find_last_not_of(" \t");
  return text.substr(begin, end - begin + 1);
}

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  std::size_t begin = 0;
  while (true) {
    const std::size_t end = text.find(separator, begin);
    parts.push_back(text.substr(begin, end == std::string_view::npos ? std::string_view::npos : end - begin));
    if (end == std::string_view::npos) return parts;
    begin = end + 1;
  }
}

// One number of an item. `whole` is the selection text and `item` the item, for the message.
int parse_frame_number(std::string_view whole, std::string_view item, std::string_view text) {
  text = trimmed(text);
  if (text.empty()) fail("frame selection \"{}\": \"{}\" is missing a number", whole, item);
  int value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (stop == end && error == std::errc() && value < 0)
    fail("frame selection \"{}\": \"{}\" is negative; frames count from 0", whole, text);
  if (stop == end && error == std::errc::result_out_of_range)
    fail("frame selection \"{}\": \"{}\" is too large", whole, text);
  if (stop != end || error != std::errc())
    fail("frame selection \"{}\": \"{}\" is not a frame number (expected N, A:B or A:B:step)", whole, item);
  return value;
}

}  // namespace

FrameSelection FrameSelection::parse(std::string_view text) {
  FrameSelection selection;
  selection.text_ = std::string(text);
  if (trimmed(text).empty()) fail("frame selection \"{}\": no frames given", text);
  for (const std::string_view raw_item : split(text, ',')) {
    const std::string_view item = trimmed(raw_item);
    if (item.empty()) fail("frame selection \"{}\": empty item between commas", text);
    const std::vector<std::string_view> numbers = split(item, ':');
    if (numbers.size() > 3)
      fail("frame selection \"{}\": \"{}\" has more than three parts (expected N, A:B or A:B:step)", text, item);
    Item parsed;
    parsed.text = std::string(item);
    parsed.first = parse_frame_number(text, item, numbers[0]);
    parsed.last = numbers.size() >= 2 ? parse_frame_number(text, item, numbers[1]) : parsed.first;
    if (numbers.size() == 3) {
      parsed.step = parse_frame_number(text, item, numbers[2]);
      if (parsed.step == 0) fail("frame selection \"{}\": \"{}\" has step 0; the step must be at least 1", text, item);
    }
    if (parsed.last < parsed.first)
      fail("frame selection \"{}\": \"{}\" ends at frame {} before it starts at frame {}", text, item, parsed.last,
           parsed.first);
    parsed.last = parsed.first + (parsed.last - parsed.first) / parsed.step * parsed.step;
    selection.items_.push_back(std::move(parsed));
  }
  return selection;
}

FrameSelection FrameSelection::all() {
  FrameSelection selection;
  selection.text_ = "all";
  selection.all_ = true;
  return selection;
}

std::vector<int> FrameSelection::resolve(int frame_count) const {
  if (frame_count <= 0) fail("frame selection \"{}\": the walkthrough has no frames", text_);
  std::vector<int> frames;
  if (all_) {
    frames.reserve(static_cast<std::size_t>(frame_count));
    for (int frame = 0; frame < frame_count; ++frame) frames.push_back(frame);
    return frames;
  }
  // Checked before anything is expanded, so "0:2000000000" fails fast instead of filling memory.
  for (const Item& item : items_) {
    if (item.last < frame_count) continue;
    if (item.first == item.last && item.text.find(':') == std::string::npos)
      fail("frame selection \"{}\": frame {} is past the walkthrough's last frame {}", text_, item.last,
           frame_count - 1);
    fail("frame selection \"{}\": frame {} (in \"{}\") is past the walkthrough's last frame {}", text_, item.last,
         item.text, frame_count - 1);
  }
  std::vector<bool> selected(static_cast<std::size_t>(frame_count), false);
  for (const Item& item : items_)
    for (long long frame = item.first; frame <= item.last; frame += item.step) selected[static_cast<std::size_t>(frame)] = true;
  for (int frame = 0; frame < frame_count; ++frame)
    if (selected[static_cast<std::size_t>(frame)]) frames.push_back(frame);
  return frames;
}

}  // namespace glint
