#include "poi_steps.hpp"

#include <cstdlib>
#include <cstring>

namespace pxflow::ref {

std::uint16_t feature(const FrameView& prev, int i, int j, OpCounts& cnt) {
  auto q = [&](int c, int r) { return int{prev.at(i + 2 + c, j + 2 + r)}; };
  int sum = 0;
  for (int r = 0; r < 3; ++r) {  // vertical neighbours: rows r and r+1, one 4-byte op each
    for (int c = 0; c < 4; ++c) sum += std::abs(q(c, r) - q(c, r + 1));
    ++cnt.sad_ops;
  }
  for (int c = 0; c < 3; ++c) {  // horizontal neighbours: columns c and c+1, one op each
    for (int r = 0; r < 4; ++r) sum += std::abs(q(c, r) - q(c + 1, r));
    ++cnt.sad_ops;
  }
  return static_cast<std::uint16_t>(sum);  // <= 24 * 255 = 6120
}

namespace {

// A row's 8 pixels as one word: the sanitizer build checks one 8-byte read instead of eight.
std::uint64_t row_word(const std::uint8_t* p) {
  std::uint64_t w;
  std::memcpy(&w, p, sizeof w);
  return w;
}

// The SAD of two rows of 8 pixels, pixel c in byte c of each word (the same byte order in both).
std::uint32_t row_sad(std::uint64_t a, std::uint64_t b) {
  std::uint32_t sad = 0;
  for (int c = 0; c < 8; ++c)
    sad += static_cast<std::uint32_t>(std::abs(static_cast<int>((a >> (8 * c)) & 0xFF) -
                                               static_cast<int>((b >> (8 * c)) & 0xFF)));
  return sad;
}

}  // namespace

Match integer_search(const FramePair& f, int i, int j, int S, OpCounts& cnt) {
  // block_sad's sum, pixel by pixel, with prev's block read once and every row (prev's and the
  // candidate's) as a word: the search is most of the time of every check (and of the test suite,
  // ASan's above all), and block_sad's value callable hides the rows from the compiler.
  std::uint64_t block[8];
  for (int r = 0; r < 8; ++r) block[r] = row_word(f.prev.row(j + r) + i);
  Match best{0, 0, 0xFFFFFFFFu};  // the sentinel: any real SAD replaces it
  for (int dy = -S; dy <= S; ++dy) {
    for (int dx = -S; dx <= S; ++dx) {
      std::uint32_t sad = 0;
      for (int r = 0; r < 8; ++r)
        sad += row_sad(block[r], row_word(f.next.row(j + dy + r) + i + dx));
      cnt.sad_ops += 16;                         // two 4-byte halves per row, as block_sad charges
      if (sad < best.sad) best = {dx, dy, sad};  // strict: a tie keeps the earlier candidate
    }
  }
  return best;
}

void select_half_pixel(PoiRecord& rec, const Match& m, const std::uint32_t sub[8]) {
  std::uint32_t best = m.sad;
  int dir = kDirNone;
  for (int k = 0; k < 8; ++k) {
    rec.sub[k] = static_cast<std::uint16_t>(sub[k]);
    if (sub[k] < best) {  // strict: a half step must beat the integer match and lower k's
      best = sub[k];
      dir = k;
    }
  }
  record_direction(rec, m, dir);
}

}  // namespace pxflow::ref
