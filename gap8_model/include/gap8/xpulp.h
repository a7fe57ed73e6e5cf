// Semantics of the Xpulp (PULPv2, GAP8's RI5CY) instructions the model implements, as pure
// functions so they can be unit-tested against the sources' values. Sources, cited per group:
//   [GVSOC]  gvsoc-core models/cpu/iss/include/isa_lib/int.h and include/isa/pulp_v2.hpp
//            (GreenWaves' ISS; its GAP8 core runs the pulpv2 subset);
//   [RI5CY]  the RI5CY user manual, pulp-platform/riscv doc/user_manual.doc (2018, commit
//            bc2960e), chapters "ALU extensions", "MAC", "Vectorial";
//   [RTL]    RI5CY's RTL of the same generation, pulp-platform/riscv riscv_alu.sv and
//            riscv_mult.sv at commit 40a48c6 (March 2018);
//   [TESTS]  pulp-platform/riscv-tests, branch xpulp-dev, isa/rv32uxpulp*/.
// Where the sources disagree, the comment says which one the model follows and why.
// Lanes: a 32-bit register holds four bytes (.b, lane i = bits 8i..8i+7) or two half-words
// (.h, lane i = bits 16i..16i+15).
#pragma once

#include <cstdint>
#include <type_traits>

namespace gap8::xpulp {

template <typename T>
constexpr int kLanes = 4 / static_cast<int>(sizeof(T));
template <typename T>
constexpr int kLaneBits = 8 * static_cast<int>(sizeof(T));

// Lane i of x as type T (int8_t, uint8_t, int16_t or uint16_t).
template <typename T>
inline T Get(uint32_t x, int i) {
  return static_cast<T>(x >> (kLaneBits<T> * i));
}

// Applies f lane by lane; each result is truncated to the lane (the hardware's lane width).
template <typename T, typename F>
inline uint32_t Map(uint32_t a, uint32_t b, F f) {
  using U = std::make_unsigned_t<T>;
  uint32_t r = 0;
  for (int i = 0; i < kLanes<T>; ++i) {
    const U lane = static_cast<U>(f(Get<T>(a, i), Get<T>(b, i)));
    r |= static_cast<uint32_t>(lane) << (kLaneBits<T> * i);
  }
  return r;
}

// pv.*.sc: "operand 2 is treated as a scalar and replicated two or four times ... The LSP is
// used" [RI5CY]; .sci replicates the 6-bit immediate the same way.
// p.beqimm / p.bneimm: the 5-bit signed immediate kept in the rs2 field [RI5CY "Immediate
// Branching"].
constexpr int32_t BranchImm5(uint32_t rs2_field) {
  return static_cast<int8_t>(static_cast<uint8_t>(rs2_field << 3)) >> 3;
}

inline uint32_t SplatByte(uint32_t x) { return (x & 0xFFu) * 0x01010101u; }
inline uint32_t SplatHalf(uint32_t x) { return (x & 0xFFFFu) * 0x00010001u; }

// ---- Vector ALU [RI5CY "Vectorial ALU Operations"; GVSOC VEC_OP / VEC_EXPR] ----
template <typename T>
uint32_t Add(uint32_t a, uint32_t b) {
  return Map<T>(a, b, [](T x, T y) { return x + y; });  // wraps in the lane
}
template <typename T>
uint32_t Sub(uint32_t a, uint32_t b) {
  return Map<T>(a, b, [](T x, T y) { return x - y; });
}
// pv.avg / pv.avgu: the sum is taken in the lane, so its carry is lost, then shifted:
// arithmetic for avg, logical for avgu. [GVSOC] VEC_EXPR(AVGU, ..., ((uint8_t)(tmp_a[i] +
// tmp_b[i]) >> 1)) and VEC_EXPR(AVG, ..., ((int8_t)(tmp_a[i] + tmp_b[i]) >> 1)); GreenWaves'
// builtins.h ("addition performed on 8 bits"); [TESTS] pv_avgu: pv.avgu.b 0x8F75F8E9,
// 0xDD666F70 = 0x366D332C. It is therefore NOT a floor average whenever the lane sum overflows.
template <typename T>
uint32_t Avg(uint32_t a, uint32_t b) {
  return Map<T>(a, b, [](T x, T y) { return static_cast<T>(static_cast<T>(x + y) >> 1); });
}
template <typename T>
uint32_t Min(uint32_t a, uint32_t b) {
  return Map<T>(a, b, [](T x, T y) { return x < y ? x : y; });
}
template <typename T>
uint32_t Max(uint32_t a, uint32_t b) {
  return Map<T>(a, b, [](T x, T y) { return x > y ? x : y; });
}
// Shifts use the low log2(lane bits) bits of the shift lane [GVSOC: & 0x7 for .b, & 0xF for
// .h]; srl/sll on unsigned lanes (logical), sra on signed lanes (arithmetic).
template <typename T>
uint32_t Shr(uint32_t a, uint32_t b) {
  return Map<T>(a, b, [](T x, T y) { return x >> (y & (kLaneBits<T> - 1)); });
}
template <typename T>
uint32_t Shl(uint32_t a, uint32_t b) {
  return Map<T>(a, b, [](T x, T y) { return x << (y & (kLaneBits<T> - 1)); });
}
// pv.abs: |-128| wraps to 0x80 (|-32768| to 0x8000) in the lane [GVSOC lib_VEC_ABS].
template <typename T>
uint32_t Abs(uint32_t a) {
  return Map<T>(a, 0, [](T x, T) { return x < 0 ? -x : x; });
}
// pv.cmp*: all ones in a lane where the comparison holds, else 0 [GVSOC VEC_CMP].
template <typename T, typename Cmp>
uint32_t Compare(uint32_t a, uint32_t b, Cmp cmp) {
  return Map<T>(a, b, [cmp](T x, T y) { return cmp(x, y) ? -1 : 0; });
}

// pv.extract(u): lane `index` of a, sign- (T signed) or zero-extended; pv.insert: lane `index`
// of c (rd) replaced by a's low lane, the rest of rd kept [RI5CY; GVSOC lib_VEC_EXT/INS]. The
// index is the immediate's low 2 (.b) or 1 (.h) bits: the manual defines only those lanes.
template <typename T>
uint32_t Extract(uint32_t a, uint32_t index) {
  return static_cast<uint32_t>(static_cast<int32_t>(Get<T>(a, index & (kLanes<T> - 1))));
}
template <typename T>
uint32_t Insert(uint32_t c, uint32_t a, uint32_t index) {
  const int shift = kLaneBits<T> * static_cast<int>(index & (kLanes<T> - 1));
  const uint32_t mask = static_cast<uint32_t>(static_cast<std::make_unsigned_t<T>>(~0u)) << shift;
  return (c & ~mask) | ((a << shift) & mask);
}

// Dot products: sum of lane products, modulo 2^32 [RI5CY "Dot Product Instructions"; GVSOC
// VEC_DOTP / VEC_SDOT]. TA, TB give each operand's signedness (dotup: u x u, dotusp: u x s,
// dotsp: s x s); sdot* add the accumulator rd.
template <typename TA, typename TB>
uint32_t Dot(uint32_t a, uint32_t b) {
  uint32_t s = 0;
  for (int i = 0; i < kLanes<TA>; ++i)
    s += static_cast<uint32_t>(static_cast<int32_t>(Get<TA>(a, i))) *
         static_cast<uint32_t>(static_cast<int32_t>(Get<TB>(b, i)));
  return s;
}

// pv.shuffle: lane i of the result is lane sel_i of a, sel_i = the low 2 (.b) or 1 (.h) bits
// of lane i of b. pv.shuffle2: bit 2 (.b) or 1 (.h) of sel lane i picks a (rs1) when set, c
// (rd) when clear [RI5CY "Shuffle and Pack"; GVSOC lib_VEC_SHUFFLE / SHUFFLE2 under RISCV].
template <typename T>
uint32_t Shuffle2(uint32_t c, uint32_t a, uint32_t b) {
  using U = std::make_unsigned_t<T>;
  uint32_t r = 0;
  for (int i = 0; i < kLanes<T>; ++i) {
    const uint32_t sel = static_cast<U>(Get<T>(b, i));
    const uint32_t src = (sel & kLanes<T>) ? a : c;
    r |= static_cast<uint32_t>(Get<U>(src, sel & (kLanes<T> - 1))) << (kLaneBits<T> * i);
  }
  return r;
}
template <typename T>
uint32_t Shuffle(uint32_t a, uint32_t b) {
  return Shuffle2<T>(a, a, b);  // both sources a: the selecting bit does not matter
}
// pv.pack.h: rd = rs1[15:0] : rs2[15:0]; pv.packhi.b / packlo.b write rs1[7:0], rs2[7:0] into
// the high / low half of rd and keep the other half [RI5CY; GVSOC lib_VEC_PACK*].
inline uint32_t PackH(uint32_t a, uint32_t b) { return (a << 16) | (b & 0xFFFFu); }
inline uint32_t PackHiB(uint32_t c, uint32_t a, uint32_t b) {
  return ((a & 0xFFu) << 24) | ((b & 0xFFu) << 16) | (c & 0xFFFFu);
}
inline uint32_t PackLoB(uint32_t c, uint32_t a, uint32_t b) {
  return ((a & 0xFFu) << 8) | (b & 0xFFu) | (c & 0xFFFF0000u);
}

// ---- GAP8-only SIMD extensions [GVSOC-GAP: gap_sdk's GVSOC, models/cpu/iss isa_riscv_gen.py
// subset `gap8` and include/rvXgap8.hpp, with gvsoc-core isa_lib/int.h for the lib_* bodies].
// A single source: GreenWaves' own simulator; neither the RI5CY manual nor its RTL has them.
// pv.add/sub.{h,b}.div2/div4: the lane sum or difference wrapped in the signed lane, then an
// arithmetic shift (VEC_OP_DIV2 / DIV4: ((elemType)(a op b)) >> 1 or 2).
template <typename T>
uint32_t AddShift(uint32_t a, uint32_t b, int shift) {
  return Map<T>(a, b, [shift](T x, T y) { return static_cast<T>(static_cast<T>(x + y) >> shift); });
}
template <typename T>
uint32_t SubShift(uint32_t a, uint32_t b, int shift) {
  return Map<T>(a, b, [shift](T x, T y) { return static_cast<T>(static_cast<T>(x - y) >> shift); });
}
// pv.cplxmul.s: complex numbers as (im = high half, re = low half), Q15: re = (a_re b_re -
// a_im b_im) >> shift, im = (a_im b_re + a_re b_im) >> shift, each truncated to 16 bits, with
// shift 15 (.div2: 16, .div4: 17) [lib_CPLXMULS, lib_CPLXMULS_DIV2/4].
inline uint32_t CplxMul(uint32_t a, uint32_t b, int shift) {
  const int64_t ar = static_cast<int16_t>(a), ai = static_cast<int16_t>(a >> 16);
  const int64_t br = static_cast<int16_t>(b), bi = static_cast<int16_t>(b >> 16);
  const auto re = static_cast<uint16_t>((ar * br - ai * bi) >> shift);
  const auto im = static_cast<uint16_t>((ai * br + ar * bi) >> shift);
  return (static_cast<uint32_t>(im) << 16) | re;
}
// pv.cplxconj.h: the imaginary (high) half negated [lib_CPLX_CONJ_16].
inline uint32_t CplxConj(uint32_t a) {
  return (static_cast<uint32_t>(static_cast<uint16_t>(-static_cast<int16_t>(a >> 16))) << 16) |
         (a & 0xFFFFu);
}
// pv.subrotmj.h: (a - b) * -j: re = a_im - b_im, im = b_re - a_re, each in the lane and shifted
// arithmetically by 0 / 1 / 2 (.div2, .div4) [lib_VEC_ADD_16_ROTMJ*].
inline uint32_t SubRotmj(uint32_t a, uint32_t b, int shift) {
  const auto re = static_cast<int16_t>(static_cast<int16_t>((a >> 16) - (b >> 16)) >> shift);
  const auto im = static_cast<int16_t>(static_cast<int16_t>(b - a) >> shift);
  return (static_cast<uint32_t>(static_cast<uint16_t>(im)) << 16) | static_cast<uint16_t>(re);
}
// pv.pack.h.h: rd = rs1[31:16] : rs2[31:16] [lib_VEC_PACK_SC_H_16]; pv.pack.l.h is pv.pack.h.
inline uint32_t PackHighHalves(uint32_t a, uint32_t b) { return (a & 0xFFFF0000u) | (b >> 16); }

// ---- Scalar ALU [RI5CY "General ALU Operations", "Bit Manipulation"] ----
inline uint32_t AbsW(uint32_t a) {
  return static_cast<int32_t>(a) < 0 ? 0u - a : a;  // p.abs of INT32_MIN stays INT32_MIN
}
inline uint32_t MinW(uint32_t a, uint32_t b) {
  return static_cast<int32_t>(a) < static_cast<int32_t>(b) ? a : b;
}
inline uint32_t MaxW(uint32_t a, uint32_t b) {
  return static_cast<int32_t>(a) > static_cast<int32_t>(b) ? a : b;
}
inline uint32_t MinuW(uint32_t a, uint32_t b) { return a < b ? a : b; }
inline uint32_t MaxuW(uint32_t a, uint32_t b) { return a > b ? a : b; }
// p.avgu: (rs1 + rs2) >> 1 on 32 bits, the carry lost [GVSOC lib_AVGU on unsigned int].
inline uint32_t AvguW(uint32_t a, uint32_t b) { return (a + b) >> 1; }
inline uint32_t Slet(uint32_t a, uint32_t b) {
  return static_cast<int32_t>(a) <= static_cast<int32_t>(b);
}
inline uint32_t Sletu(uint32_t a, uint32_t b) { return a <= b; }
// p.ror: rotate right by rs2 modulo 32 ([TESTS] p_ror: a rotation by 32 returns rs1).
inline uint32_t Ror(uint32_t a, uint32_t b) {
  const uint32_t s = b & 31u;
  return s == 0 ? a : (a >> s) | (a << (32u - s));
}
// p.ff1: index of the lowest set bit, 32 for 0; p.fl1: index of the highest set bit, 32 for 0
// [RI5CY; RTL riscv_alu.sv ff_no_one ? 32].
inline uint32_t Ff1(uint32_t a) { return a == 0 ? 32u : static_cast<uint32_t>(__builtin_ctz(a)); }
inline uint32_t Fl1(uint32_t a) {
  return a == 0 ? 32u : 31u - static_cast<uint32_t>(__builtin_clz(a));
}
// p.clb: the number of leading bits equal to the sign bit, minus one (GCC's clrsb), and 0 for
// 0. [RTL] riscv_alu.sv: clb_result = ff1_result - 1 on the bit-reversed (negated when
// negative) operand, 31 for -1, 0 for 0; [GVSOC] lib_CLB = t == 0 ? 0 : __builtin_clrsb(t).
// The manual's "number of consecutive 1s or 0s from MSB" is ambiguous; the later Xpulpimg tests
// of riscv-tests (2022, a newer core) count the sign bit too (p.clb 1 = 31): not GAP8's core.
inline uint32_t Clb(uint32_t a) {
  return a == 0 ? 0u : static_cast<uint32_t>(__builtin_clrsb(static_cast<int32_t>(a)));
}
inline uint32_t Cnt(uint32_t a) { return static_cast<uint32_t>(__builtin_popcount(a)); }

// p.clip rD, rs1, Is2: clamp to [-2^(Is2-1), 2^(Is2-1) - 1]; Is2 = 0 gives [-1, 0] [RI5CY note;
// GVSOC p_clipi_exec uses max(Is2 - 1, 0)]. p.clipu: [0, 2^(Is2-1) - 1].
inline uint32_t ClipBounds(uint32_t a, int32_t low, int32_t high) {
  const int32_t v = static_cast<int32_t>(a);
  return static_cast<uint32_t>(v <= low ? low : v >= high ? high : v);
}
inline int32_t ClipHigh(uint32_t is2) { return (1 << (is2 == 0 ? 0 : is2 - 1)) - 1; }
inline uint32_t Clip(uint32_t a, uint32_t is2) {
  return ClipBounds(a, -ClipHigh(is2) - 1, ClipHigh(is2));
}
// p.clipu(r): "if rs1 <= 0, rD = 0, else if rs1 >= bound, rD = bound" in that order [RI5CY];
// [TESTS] p_clipur agrees (rs1 = 0, rs2 = -1 gives 0). GVSOC tests the bound first
// (lib_CLIPU), which differs when the register bound is negative; the model follows the manual.
inline uint32_t ClipuBound(uint32_t a, int32_t high) {
  const int32_t v = static_cast<int32_t>(a);
  return v <= 0 ? 0u : static_cast<uint32_t>(v >= high ? high : v);
}
inline uint32_t Clipu(uint32_t a, uint32_t is2) { return ClipuBound(a, ClipHigh(is2)); }
// p.clipr: [-(rs2 + 1), rs2] [RI5CY].
inline uint32_t Clipr(uint32_t a, uint32_t b) {
  return ClipBounds(a, static_cast<int32_t>(~b), static_cast<int32_t>(b));
}
inline uint32_t Clipur(uint32_t a, uint32_t b) { return ClipuBound(a, static_cast<int32_t>(b)); }

// Bit fields: `field` holds (width - 1) in bits 9..5 and the position in bits 4..0, as the
// register forms read rs2 (the immediate forms Is3, Is2 are packed the same way at decode).
// A field running past bit 31 is cut at bit 31 [RI5CY "Is3 + Is2 must be <= 32"; GVSOC
// lib_BEXTRACT and the 32-bit mask of p_insert/p_bset].
inline uint32_t FieldMask(uint32_t field) {
  const uint32_t width = ((field >> 5) & 31u) + 1, shift = field & 31u;
  const uint64_t ones = (uint64_t{1} << width) - 1;
  return static_cast<uint32_t>(ones << shift);
}
inline uint32_t BitExtractu(uint32_t a, uint32_t field) {
  return (a & FieldMask(field)) >> (field & 31u);
}
inline uint32_t BitExtract(uint32_t a, uint32_t field) {
  const uint32_t shift = field & 31u;
  const uint32_t width =
      (((field >> 5) & 31u) + 1 + shift > 32) ? 32 - shift : ((field >> 5) & 31u) + 1;
  const uint32_t v = BitExtractu(a, field);
  const uint32_t sign = 1u << (width - 1);
  return (v ^ sign) - sign;
}
inline uint32_t BitInsert(uint32_t c, uint32_t a, uint32_t field) {
  const uint32_t mask = FieldMask(field);
  return (c & ~mask) | ((a << (field & 31u)) & mask);
}
inline uint32_t BitClear(uint32_t a, uint32_t field) { return a & ~FieldMask(field); }
inline uint32_t BitSet(uint32_t a, uint32_t field) { return a | FieldMask(field); }

// ---- Multiply-accumulate [RI5CY "Multiply-Accumulate"; RTL riscv_mult.sv] ----
// p.mac / p.msu: rd +/- rs1 * rs2, low 32 bits.
inline uint32_t Mac(uint32_t c, uint32_t a, uint32_t b) { return c + a * b; }
inline uint32_t Msu(uint32_t c, uint32_t a, uint32_t b) { return c - a * b; }
// 16 x 16 multiplies p.mul{s,hhs,u,hhu}[R]N and p.mac{s,hhs,u,hhu}[R]N: the half-words
// (low, or high for hh), sign- or zero-extended, multiplied; plus rd for mac; plus the rounding
// constant 2^(Is3-1) for the R forms (0 when Is3 = 0); the 32-bit sum then shifted right by Is3,
// arithmetic when signed, logical when unsigned. [RTL] riscv_mult.sv: short_round =
// (1 << imm) >> 1, short_mac = op_c + mul + round, result = {sign, sign, short_mac[31:0]} >>>
// imm with sign = short_mac[31] only when signed: the sum wraps at 32 bits before the shift.
// GVSOC adds the rounding constant in 64 bits (lib_MAC_SL_SL_NR_R), which differs only when
// that sum crosses 2^31 (signed) or 2^32 (unsigned); the model follows the RTL.
struct Mul16 {
  bool is_signed, high, accumulate, round;
};
inline uint32_t Mul16Op(Mul16 m, uint32_t c, uint32_t a, uint32_t b, uint32_t shift) {
  const uint32_t ha = m.high ? a >> 16 : a & 0xFFFFu, hb = m.high ? b >> 16 : b & 0xFFFFu;
  const uint32_t prod =
      m.is_signed ? static_cast<uint32_t>(static_cast<int16_t>(ha) * static_cast<int16_t>(hb))
                  : ha * hb;
  shift &= 31u;
  const uint32_t round = m.round ? (1u << shift) >> 1 : 0u;
  const uint32_t sum = (m.accumulate ? c : 0u) + prod + round;
  return m.is_signed ? static_cast<uint32_t>(static_cast<int32_t>(sum) >> shift) : sum >> shift;
}

// p.add[u][R]N / p.sub[u][R]N: (a +/- b [+ 2^(shift-1)]) on 32 bits, then shifted right by
// shift, arithmetic (N, RN) or logical (uN, uRN); no rounding term when shift = 0 [RI5CY
// "p.addN ... >>> Is3"; GVSOC lib_ADD_NR / lib_ADD_NR_R wrap the sum at 32 bits as well].
inline uint32_t AddSubN(bool subtract, bool is_signed, bool round, uint32_t a, uint32_t b,
                        uint32_t shift) {
  shift &= 31u;
  const uint32_t r = round ? (1u << shift) >> 1 : 0u;
  const uint32_t sum = (subtract ? a - b : a + b) + r;
  return is_signed ? static_cast<uint32_t>(static_cast<int32_t>(sum) >> shift) : sum >> shift;
}

}  // namespace gap8::xpulp
