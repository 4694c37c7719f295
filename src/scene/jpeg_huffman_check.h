#pragma once
// A guard in front of stb_image's JPEG reader. stb_image 2.27 (Debian 12's libstb, which glint links)
// builds each Huffman table (DHT segment) from 16 code counts without checking that they add up to at
// most 256, the size of its arrays: a JPEG whose counts add up to more makes it write up to 3.8 KB past
// them, into the decoder's other tables and function pointers (a heap buffer overflow; found by the
// fuzz/ texture target, inputs in fuzz/regressions/texture/). Later stb_image versions check this.
#include <span>

namespace glint {

// Walks the JPEG's marker segments the way stb_image reads them (entropy-coded data is skipped up to
// the next marker) and throws a glint::Error naming the table when a DHT segment holds a table of
// more than 256 codes. Only the reason is in the message: callers prefix the file. Other damage is
// left to stb_image, which rejects it safely.
void check_jpeg_huffman_tables(std::span<const unsigned char> jpeg);

}  // namespace glint
