#include "synthetic.hpp"

#include <algorithm>

namespace pxflow {
namespace {

using Plane = std::vector<std::uint8_t>;

Plane noise(int w, int h, Rng& rng, int lo = 0, int hi = 255) {
  Plane p(static_cast<std::size_t>(w) * h);
  for (auto& v : p) v = static_cast<std::uint8_t>(rng.uniform(lo, hi));
  return p;
}

// A 3x3 box blur repeated `passes` times: smooth texture in which half-pixel steps are real.
Plane smooth(const Plane& in, int w, int h, int passes) {
  Plane a = in, b(in.size());
  for (int n = 0; n < passes; ++n) {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        int sum = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int xx = std::clamp(x + dx, 0, w - 1), yy = std::clamp(y + dy, 0, h - 1);
            sum += a[yy * w + xx];
          }
        b[y * w + x] = static_cast<std::uint8_t>(sum / 9);
      }
    std::swap(a, b);
  }
  return a;
}

// Floor average of each pixel with its left neighbour: content moved right by half a pixel.
Plane half_shift_x(const Plane& in, int w, int h) {
  Plane out(in.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      out[y * w + x] =
          static_cast<std::uint8_t>((in[y * w + x] + in[y * w + std::max(x - 1, 0)]) >> 1);
  return out;
}

void add_noise(Plane& p, Rng& rng, int amplitude) {
  for (auto& v : p)
    v = static_cast<std::uint8_t>(std::clamp(v + rng.uniform(-amplitude, amplitude), 0, 255));
}

OwnedPair make(std::string name, int w, int h) {
  OwnedPair op;
  op.name = std::move(name);
  op.width = w;
  op.height = h;
  return op;
}

}  // namespace

std::uint64_t Rng::next() {
  std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

int Rng::uniform(int lo, int hi) {
  const auto span = static_cast<std::uint64_t>(hi - lo) + 1;
  return lo + static_cast<int>(next() % span);
}

void shift_into(const Plane& prev, Plane& next, int w, int h, int sx, int sy,
                std::uint64_t fill_seed) {
  Rng rng(fill_seed);
  next.resize(prev.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int xs = x - sx, ys = y - sy;
      next[y * w + x] = (xs >= 0 && xs < w && ys >= 0 && ys < h)
                            ? prev[ys * w + xs]
                            : static_cast<std::uint8_t>(rng.uniform(0, 255));
    }
}

OwnedPair random_pair(int w, int h, int S, std::uint64_t seed) {
  Rng rng(seed);
  const int kind = rng.uniform(0, 5);
  static const char* kKinds[] = {"noise",       "shift",        "shift+noise",
                                 "smooth-half", "low-contrast", "unrelated"};
  OwnedPair op =
      make("random/" + std::string(kKinds[kind]) + "/seed=" + std::to_string(seed), w, h);
  const int sx = rng.uniform(-S, S), sy = rng.uniform(-S, S);
  switch (kind) {
    case 0:  // noise: both frames independent uniform noise, mostly rejected matches
    case 5:  // unrelated textures of different contrast
      op.prev = noise(w, h, rng);
      op.next = kind == 0 ? noise(w, h, rng) : smooth(noise(w, h, rng), w, h, 2);
      break;
    case 1:
    case 2:
      op.prev = noise(w, h, rng);
      shift_into(op.prev, op.next, w, h, sx, sy, rng.next());
      if (kind == 2) add_noise(op.next, rng, rng.uniform(1, 12));
      break;
    case 3: {  // smooth texture moved by a half pixel in x on top of an integer shift
      op.prev = smooth(noise(w, h, rng), w, h, rng.uniform(1, 3));
      Plane shifted;
      shift_into(op.prev, shifted, w, h, sx, sy, rng.next());
      op.next = half_shift_x(shifted, w, h);
      break;
    }
    default: {  // low contrast: few grey levels, many near-ties, features near the threshold
      const int base = rng.uniform(0, 250);
      op.prev = noise(w, h, rng, base, base + rng.uniform(1, 5));
      shift_into(op.prev, op.next, w, h, sx, sy, rng.next());
      add_noise(op.next, rng, 1);
      break;
    }
  }
  return op;
}

OwnedPair shifted_texture_pair(int w, int h, int S, std::uint64_t seed) {
  Rng rng(seed);
  OwnedPair op = make("shifted-texture/seed=" + std::to_string(seed), w, h);
  op.prev = noise(w, h, rng);
  shift_into(op.prev, op.next, w, h, rng.uniform(-S, S), rng.uniform(-S, S), rng.next());
  add_noise(op.next, rng, 3);
  return op;
}

std::vector<OwnedPair> hostile_pairs(int w, int h, int S) {
  std::vector<OwnedPair> out;
  auto add = [&](const std::string& name, auto&& prev_px, auto&& next_px) {
    OwnedPair op = make("hostile/" + name, w, h);
    op.prev.resize(static_cast<std::size_t>(w) * h);
    op.next.resize(op.prev.size());
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        op.prev[y * w + x] = static_cast<std::uint8_t>(prev_px(x, y));
        op.next[y * w + x] = static_cast<std::uint8_t>(next_px(x, y));
      }
    out.push_back(std::move(op));
  };
  auto board = [](int x, int y) { return ((x + y) & 1) ? 255 : 0; };
  add(
      "all-0", [](int, int) { return 0; }, [](int, int) { return 0; });
  add(
      "all-255", [](int, int) { return 255; }, [](int, int) { return 255; });
  add(
      "all-0-vs-255", [](int, int) { return 0; }, [](int, int) { return 255; });
  add("checkerboard", board, board);
  add("checkerboard-inverted", board, [&](int x, int y) { return 255 - board(x, y); });
  // Period 2 in both axes: every even shift matches exactly, the first in raster order wins.
  add(
      "periodic-2", [](int x, int y) { return 40 * (x & 1) + 90 * (y & 1); },
      [](int x, int y) { return 40 * (x & 1) + 90 * (y & 1); });
  add(
      "periodic-3-shifted", [](int x, int y) { return 60 * (x % 3) + 25 * (y % 3); },
      [](int x, int y) { return 60 * ((x + 1) % 3) + 25 * (y % 3); });
  // LSB-only contrast: odd/even neighbours, where floor and round-up averages differ by one.
  add(
      "lsb-only", [](int x, int y) { return 128 + ((x * 7 + y * 3) % 5 == 0); },
      [](int x, int y) { return 128 + ((x * 5 + y * 11) % 3 == 0); });
  add(
      "lsb-checkerboard", [](int x, int y) { return 200 + ((x + y) & 1) * 21; },
      [](int x, int y) { return 200 + ((x + y + 1) & 1) * 21 + (x & 1); });
  // Texture moved to every corner and edge of the search window, and one step beyond.
  Rng rng(0xED6E);
  const Plane tex = noise(w, h, rng);
  for (int sy : {-S, 0, S})
    for (int sx : {-S, 0, S, S + 1}) {
      OwnedPair op =
          make("hostile/shift(" + std::to_string(sx) + "," + std::to_string(sy) + ")", w, h);
      op.prev = tex;
      shift_into(tex, op.next, w, h, sx, sy, 99);
      out.push_back(std::move(op));
    }
  return out;
}

}  // namespace pxflow
