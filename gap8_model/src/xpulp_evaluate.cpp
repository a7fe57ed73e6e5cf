// The PULPv2 operations outside the interpreter's main switch (see Op::kXpulpEvaluated): one
// switch from the decoded op to the pure functions of include/gap8/xpulp.h, where each one's
// semantics and sources are given.
#include "gap8/decoded.h"
#include "gap8/xpulp.h"

namespace gap8 {

using namespace xpulp;  // NOLINT: this file is the table of the xpulp functions

uint32_t EvaluateXpulp(const Decoded& d, uint32_t a, uint32_t b, uint32_t c) {
  using s8 = int8_t;
  using u8 = uint8_t;
  using s16 = int16_t;
  using u16 = uint16_t;
  auto eq = [](auto x, auto y) { return x == y; };
  auto ne = [](auto x, auto y) { return x != y; };
  auto gt = [](auto x, auto y) { return x > y; };
  auto ge = [](auto x, auto y) { return x >= y; };
  auto lt = [](auto x, auto y) { return x < y; };
  auto le = [](auto x, auto y) { return x <= y; };
  switch (d.op) {
    case Op::kPvAddH:
      return Add<u16>(a, b);
    case Op::kPvSubH:
      return Sub<u16>(a, b);
    case Op::kPvAvgB:
      return Avg<s8>(a, b);
    case Op::kPvAvgH:
      return Avg<s16>(a, b);
    case Op::kPvAvguH:
      return Avg<u16>(a, b);
    case Op::kPvMinB:
      return Min<s8>(a, b);
    case Op::kPvMinH:
      return Min<s16>(a, b);
    case Op::kPvMinuH:
      return Min<u16>(a, b);
    case Op::kPvMaxB:
      return Max<s8>(a, b);
    case Op::kPvMaxH:
      return Max<s16>(a, b);
    case Op::kPvMaxuH:
      return Max<u16>(a, b);
    case Op::kPvSrlB:
      return Shr<u8>(a, b);
    case Op::kPvSrlH:
      return Shr<u16>(a, b);
    case Op::kPvSraB:
      return Shr<s8>(a, b);
    case Op::kPvSraH:
      return Shr<s16>(a, b);
    case Op::kPvSllB:
      return Shl<u8>(a, b);
    case Op::kPvSllH:
      return Shl<u16>(a, b);
    case Op::kPvOr:
      return a | b;
    case Op::kPvXor:
      return a ^ b;
    case Op::kPvAnd:
      return a & b;
    case Op::kPvAbsH:
      return Abs<s16>(a);
    case Op::kPvExtractB:
      return Extract<s8>(a, b);
    case Op::kPvExtractH:
      return Extract<s16>(a, b);
    case Op::kPvExtractuB:
      return Extract<u8>(a, b);
    case Op::kPvExtractuH:
      return Extract<u16>(a, b);
    case Op::kPvInsertB:
      return Insert<u8>(c, a, b);
    case Op::kPvInsertH:
      return Insert<u16>(c, a, b);
    case Op::kPvDotupH:
      return Dot<u16, u16>(a, b);
    case Op::kPvDotuspH:
      return Dot<u16, s16>(a, b);
    case Op::kPvDotspB:
      return Dot<s8, s8>(a, b);
    case Op::kPvDotspH:
      return Dot<s16, s16>(a, b);
    case Op::kPvSdotupH:
      return c + Dot<u16, u16>(a, b);
    case Op::kPvSdotuspH:
      return c + Dot<u16, s16>(a, b);
    case Op::kPvSdotspB:
      return c + Dot<s8, s8>(a, b);
    case Op::kPvSdotspH:
      return c + Dot<s16, s16>(a, b);
    case Op::kPvShuffleB:
      return Shuffle<u8>(a, b);
    case Op::kPvShuffleH:
      return Shuffle<u16>(a, b);
    case Op::kPvShuffle2B:
      return Shuffle2<u8>(c, a, b);
    case Op::kPvShuffle2H:
      return Shuffle2<u16>(c, a, b);
    case Op::kPvPackH:
      return PackH(a, b);
    case Op::kPvPackHiB:
      return PackHiB(c, a, b);
    case Op::kPvPackLoB:
      return PackLoB(c, a, b);
    case Op::kPvCmpEqB:
      return Compare<s8>(a, b, eq);
    case Op::kPvCmpEqH:
      return Compare<s16>(a, b, eq);
    case Op::kPvCmpNeB:
      return Compare<s8>(a, b, ne);
    case Op::kPvCmpNeH:
      return Compare<s16>(a, b, ne);
    case Op::kPvCmpGtB:
      return Compare<s8>(a, b, gt);
    case Op::kPvCmpGtH:
      return Compare<s16>(a, b, gt);
    case Op::kPvCmpGeB:
      return Compare<s8>(a, b, ge);
    case Op::kPvCmpGeH:
      return Compare<s16>(a, b, ge);
    case Op::kPvCmpLtB:
      return Compare<s8>(a, b, lt);
    case Op::kPvCmpLtH:
      return Compare<s16>(a, b, lt);
    case Op::kPvCmpLeB:
      return Compare<s8>(a, b, le);
    case Op::kPvCmpLeH:
      return Compare<s16>(a, b, le);
    case Op::kPvCmpGtuB:
      return Compare<u8>(a, b, gt);
    case Op::kPvCmpGtuH:
      return Compare<u16>(a, b, gt);
    case Op::kPvCmpGeuB:
      return Compare<u8>(a, b, ge);
    case Op::kPvCmpGeuH:
      return Compare<u16>(a, b, ge);
    case Op::kPvCmpLtuB:
      return Compare<u8>(a, b, lt);
    case Op::kPvCmpLtuH:
      return Compare<u16>(a, b, lt);
    case Op::kPvCmpLeuB:
      return Compare<u8>(a, b, le);
    case Op::kPvCmpLeuH:
      return Compare<u16>(a, b, le);
    case Op::kPvAddDivH:
      return AddShift<s16>(a, b, d.imm);
    case Op::kPvAddDivB:
      return AddShift<s8>(a, b, d.imm);
    case Op::kPvSubDivH:
      return SubShift<s16>(a, b, d.imm);
    case Op::kPvSubDivB:
      return SubShift<s8>(a, b, d.imm);
    case Op::kPvCplxMulS:
      return CplxMul(a, b, d.imm);
    case Op::kPvCplxConjH:
      return CplxConj(a);
    case Op::kPvSubRotmjH:
      return SubRotmj(a, b, d.imm);
    case Op::kPvPackHH:
      return PackHighHalves(a, b);
    case Op::kPAvgu:
      return AvguW(a, b);
    case Op::kPSlet:
      return Slet(a, b);
    case Op::kPSletu:
      return Sletu(a, b);
    case Op::kPRor:
      return Ror(a, b);
    case Op::kPFf1:
      return Ff1(a);
    case Op::kPFl1:
      return Fl1(a);
    case Op::kPClb:
      return Clb(a);
    case Op::kPCnt:
      return Cnt(a);
    case Op::kPExths:
      return static_cast<uint32_t>(static_cast<int16_t>(a));
    case Op::kPExthz:
      return a & 0xFFFFu;
    case Op::kPExtbs:
      return static_cast<uint32_t>(static_cast<int8_t>(a));
    case Op::kPExtbz:
      return a & 0xFFu;
    case Op::kPClip:
      return Clip(a, b);
    case Op::kPClipu:
      return Clipu(a, b);
    case Op::kPClipr:
      return Clipr(a, b);
    case Op::kPClipur:
      return Clipur(a, b);
    case Op::kPExtract:
      return BitExtract(a, b);
    case Op::kPExtractu:
      return BitExtractu(a, b);
    case Op::kPInsert:
      return BitInsert(c, a, b);
    case Op::kPBclr:
      return BitClear(a, b);
    case Op::kPBset:
      return BitSet(a, b);
    case Op::kPMac:
      return Mac(c, a, b);
    case Op::kPMsu:
      return Msu(c, a, b);
    case Op::kPMul16: {
      const Mul16 m{(d.width & kMulSigned) != 0, (d.width & kMulHigh) != 0,
                    (d.width & kMulAccumulate) != 0, (d.width & kMulRound) != 0};
      return Mul16Op(m, c, a, b, static_cast<uint32_t>(d.imm));
    }
    case Op::kPAddN:
      return AddSubN((d.width & kAddNSubtract) != 0, (d.width & kAddNSigned) != 0,
                     (d.width & kAddNRound) != 0, a, b, static_cast<uint32_t>(d.imm));
    case Op::kPAddNr:  // rD = (rD +/- rs1 ...) >> rs2[4:0]
      return AddSubN((d.width & kAddNSubtract) != 0, (d.width & kAddNSigned) != 0,
                     (d.width & kAddNRound) != 0, c, a, b);
    default:
      return 0;  // unreachable: the decoder emits no other op at or above kXpulpEvaluated
  }
}

}  // namespace gap8
