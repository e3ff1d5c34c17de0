// SPDX-License-Identifier: Apache-2.0
#pragma once
// A minimal PNG reader for the tests that look at screenshots (headless Chromium): 8-bit RGB or
// RGBA, not interlaced, with its own inflate (RFC 1950/1951: stored, fixed and dynamic Huffman
// blocks). No dependency; throws std::runtime_error on anything else.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace ncpost::test {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  ///< width × height × 3
  const std::uint8_t* at(int x, int y) const { return &rgb[3 * (static_cast<std::size_t>(y) * width + x)]; }
};

namespace png_detail {

struct BitReader {
  const std::vector<std::uint8_t>& in;
  std::size_t pos = 0;
  int bit = 0;
  int get(int n) {
    int v = 0;
    for (int i = 0; i < n; ++i) {
      if (pos >= in.size()) throw std::runtime_error("inflate: out of data");
      v |= ((in[pos] >> bit) & 1) << i;
      if (++bit == 8) bit = 0, ++pos;
    }
    return v;
  }
};

struct Huffman {
  std::vector<int> count, symbol;
  Huffman(const int* lengths, int n) : count(16, 0), symbol(static_cast<std::size_t>(n), 0) {
    for (int i = 0; i < n; ++i) ++count[static_cast<std::size_t>(lengths[i])];
    count[0] = 0;
    std::vector<int> offs(16, 0);
    for (int l = 1; l < 16; ++l)
      offs[static_cast<std::size_t>(l)] =
          offs[static_cast<std::size_t>(l - 1)] + count[static_cast<std::size_t>(l - 1)];
    for (int i = 0; i < n; ++i)
      if (lengths[i]) symbol[static_cast<std::size_t>(offs[static_cast<std::size_t>(lengths[i])]++)] = i;
  }
  int decode(BitReader& r) const {
    int code = 0, first = 0, index = 0;
    for (int l = 1; l < 16; ++l) {
      code |= r.get(1);
      const int c = count[static_cast<std::size_t>(l)];
      if (code - c < first) return symbol[static_cast<std::size_t>(index + (code - first))];
      index += c;
      first = (first + c) << 1;
      code <<= 1;
    }
    throw std::runtime_error("inflate: bad code");
  }
};

inline std::vector<std::uint8_t> inflate_zlib(const std::vector<std::uint8_t>& z) {
  static const int lbase[29] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                                31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
  static const int lext[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
  static const int dbase[30] = {1,   2,   3,   4,   5,   7,    9,    13,   17,   25,   33,   49,   65,    97,    129,
                                193, 257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
  static const int dext[30] = {0, 0, 0, 0, 1, 1, 2, 2,  3,  3,  4,  4,  5,  5,  6,
                               6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};
  std::vector<std::uint8_t> out;
  BitReader r{z, 2, 0};  // skip the zlib header (CMF, FLG)
  int last = 0;
  while (!last) {
    last = r.get(1);
    const int type = r.get(2);
    if (type == 0) {
      if (r.bit) r.bit = 0, ++r.pos;
      if (r.pos + 4 > z.size()) throw std::runtime_error("inflate: stored block");
      const std::size_t len = z[r.pos] | (z[r.pos + 1] << 8);
      r.pos += 4;
      if (r.pos + len > z.size()) throw std::runtime_error("inflate: stored block");
      out.insert(out.end(), z.begin() + static_cast<long>(r.pos), z.begin() + static_cast<long>(r.pos + len));
      r.pos += len;
      continue;
    }
    if (type == 3) throw std::runtime_error("inflate: bad block type");
    int lengths[320];
    int nlen = 288, ndist = 30;
    if (type == 1) {
      for (int i = 0; i < 144; ++i) lengths[i] = 8;
      for (int i = 144; i < 256; ++i) lengths[i] = 9;
      for (int i = 256; i < 280; ++i) lengths[i] = 7;
      for (int i = 280; i < 288; ++i) lengths[i] = 8;
      for (int i = 0; i < 30; ++i) lengths[288 + i] = 5;
    } else {
      nlen = r.get(5) + 257;
      ndist = r.get(5) + 1;
      const int ncode = r.get(4) + 4;
      static const int order[19] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};
      int cl[19] = {};
      for (int i = 0; i < ncode; ++i) cl[order[i]] = r.get(3);
      const Huffman h(cl, 19);
      int i = 0;
      while (i < nlen + ndist) {
        int sym = h.decode(r);
        if (sym < 16) {
          lengths[i++] = sym;
          continue;
        }
        int value = 0, repeat = 0;
        if (sym == 16) {
          if (i == 0) throw std::runtime_error("inflate: repeat with no length");
          value = lengths[i - 1];
          repeat = 3 + r.get(2);
        } else if (sym == 17) {
          repeat = 3 + r.get(3);
        } else {
          repeat = 11 + r.get(7);
        }
        if (i + repeat > nlen + ndist) throw std::runtime_error("inflate: too many lengths");
        while (repeat--) lengths[i++] = value;
      }
    }
    const Huffman lit(lengths, nlen), dist(lengths + nlen, ndist);
    for (;;) {
      const int sym = lit.decode(r);
      if (sym < 256) {
        out.push_back(static_cast<std::uint8_t>(sym));
      } else if (sym == 256) {
        break;
      } else {
        const int s = sym - 257;
        if (s >= 29) throw std::runtime_error("inflate: bad length");
        const int len = lbase[s] + r.get(lext[s]);
        const int d = dist.decode(r);
        if (d >= 30) throw std::runtime_error("inflate: bad distance");
        const std::size_t back = static_cast<std::size_t>(dbase[d] + r.get(dext[d]));
        if (back > out.size()) throw std::runtime_error("inflate: distance too far");
        for (int k = 0; k < len; ++k) out.push_back(out[out.size() - back]);
      }
    }
  }
  return out;
}

inline std::uint32_t be32(const std::string& s, std::size_t at) {
  return (std::uint32_t{static_cast<std::uint8_t>(s[at])} << 24) |
         (std::uint32_t{static_cast<std::uint8_t>(s[at + 1])} << 16) |
         (std::uint32_t{static_cast<std::uint8_t>(s[at + 2])} << 8) |
         std::uint32_t{static_cast<std::uint8_t>(s[at + 3])};
}

}  // namespace png_detail

/// Decodes the bytes of a PNG file (8-bit RGB/RGBA, not interlaced) to RGB.
inline Image decode_png(const std::string& file) {
  using namespace png_detail;
  if (file.size() < 8 || file.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0) throw std::runtime_error("not a PNG");
  Image img;
  int channels = 0;
  std::vector<std::uint8_t> idat;
  for (std::size_t at = 8; at + 8 <= file.size();) {
    const std::uint32_t len = be32(file, at);
    const std::string type = file.substr(at + 4, 4);
    if (at + 12 + len > file.size()) throw std::runtime_error("PNG: truncated chunk");
    if (type == "IHDR") {
      img.width = static_cast<int>(be32(file, at + 8));
      img.height = static_cast<int>(be32(file, at + 12));
      const int depth = static_cast<std::uint8_t>(file[at + 16]), colour = static_cast<std::uint8_t>(file[at + 17]);
      if (depth != 8 || (colour != 2 && colour != 6) || file[at + 20] != 0)
        throw std::runtime_error("PNG: not 8-bit RGB(A)");
      channels = colour == 2 ? 3 : 4;
    } else if (type == "IDAT") {
      idat.insert(idat.end(), file.begin() + static_cast<long>(at + 8), file.begin() + static_cast<long>(at + 8 + len));
    }
    at += 12 + len;
  }
  if (!channels) throw std::runtime_error("PNG: no IHDR");
  const std::vector<std::uint8_t> raw = inflate_zlib(idat);
  const std::size_t stride = static_cast<std::size_t>(img.width) * channels;
  if (raw.size() < (stride + 1) * img.height) throw std::runtime_error("PNG: short image data");
  std::vector<std::uint8_t> cur(stride), prev(stride, 0);
  img.rgb.resize(static_cast<std::size_t>(img.width) * img.height * 3);
  for (int y = 0; y < img.height; ++y) {
    const std::uint8_t* line = &raw[(stride + 1) * y];
    const int filter = line[0];
    for (std::size_t i = 0; i < stride; ++i) {
      const int a = i >= static_cast<std::size_t>(channels) ? cur[i - channels] : 0, b = prev[i],
                c = i >= static_cast<std::size_t>(channels) ? prev[i - channels] : 0;
      int pred = 0;
      switch (filter) {
        case 0:
          pred = 0;
          break;
        case 1:
          pred = a;
          break;
        case 2:
          pred = b;
          break;
        case 3:
          pred = (a + b) / 2;
          break;
        case 4: {
          const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
          pred = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
          break;
        }
        default:
          throw std::runtime_error("PNG: bad filter");
      }
      cur[i] = static_cast<std::uint8_t>(line[1 + i] + pred);
    }
    for (int x = 0; x < img.width; ++x)
      for (int k = 0; k < 3; ++k)
        img.rgb[3 * (static_cast<std::size_t>(y) * img.width + x) + k] =
            cur[static_cast<std::size_t>(x) * channels + k];
    std::swap(cur, prev);
  }
  return img;
}

}  // namespace ncpost::test
