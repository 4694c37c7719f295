#pragma once
// A guard in front of stb_image 2.27 (Debian 12's libstb, which glint links) for the inputs it
// mishandles, all found by the fuzz/ texture target (inputs in fuzz/regressions/texture/); later
// stb_image versions check them:
//  - a JPEG Huffman table (DHT segment) whose 16 code counts add up to more than 256: stb_image writes
//    up to 3.8 KB past its 257-byte arrays, into the decoder's other tables and function pointers (a
//    heap buffer overflow);
//  - a JPEG scan that decodes with a Huffman table no DHT segment defined: stb_image reads the table
//    from uninitialised memory and indexes its arrays with what it finds (reads far out of bounds);
//  - a JPEG scan that dequantises with a quantisation table no DQT segment defined (uninitialised
//    memory again: a signed int overflow in stbi__jpeg_decode_block for large values), or a 16-bit
//    quantisation table, which an 8-bit JPEG may not hold and whose entries overflow that product;
//  - a binary PNM (P5/P6) whose header numbers do not fit in an int: stb_image's parser overflows a
//    signed int (undefined behaviour);
//  - a PNG whose first image data chunk (IDAT) is empty: stb_image copies zero bytes to a null
//    pointer (undefined behaviour).
#include <span>

namespace glint {

// Throws a glint::Error saying what is wrong when the encoded image is one of the above; does nothing
// for every other input, which stb_image rejects safely when damaged. Only the reason is in the
// message: callers prefix the file.
void check_before_stb_image(std::span<const unsigned char> encoded);

}  // namespace glint
