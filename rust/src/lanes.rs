//! 128-bit vectors for the recording loops that step several chains side
//! by side: [`Quad`], four i32 lanes (a line's terms at four consecutive
//! steps, or four pieces of a circle's octant at one step each), and
//! [`Codes8`], eight 16-bit step codes. Each is one vector where the target
//! has one (wasm with SIMD; x86-64, whose every processor has SSE2), else
//! plain lanes; the operations are the few those loops need, each one
//! instruction on the vector targets.

use crate::grid::{MAX_AXES, Step};
use std::mem::MaybeUninit;

// Codes are packed to signed 16 bits and stored eight as 16 bytes: a
// code's bits (moving 0..MAX_AXES, negative 8..8 + MAX_AXES) stay below
// 2^14, and a Step is a u16.
const _: () = assert!(MAX_AXES <= 6 && std::mem::size_of::<Step>() == 2);

/// Four i32 lanes. Callers keep every value and constant below 2^30 in
/// size, so no sum or difference of two overflows (the plain lanes'
/// compare is a subtraction).
#[derive(Clone, Copy)]
pub(crate) struct Quad(
    #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))] core::arch::wasm32::v128,
    #[cfg(target_arch = "x86_64")] core::arch::x86_64::__m128i,
    #[cfg(not(any(
        all(target_arch = "wasm32", target_feature = "simd128"),
        target_arch = "x86_64"
    )))]
    [i32; 4],
);

/// Eight 16-bit lanes: step codes, or the masks that choose them.
#[derive(Clone, Copy)]
pub(crate) struct Codes8(
    #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))] core::arch::wasm32::v128,
    #[cfg(target_arch = "x86_64")] core::arch::x86_64::__m128i,
    #[cfg(not(any(
        all(target_arch = "wasm32", target_feature = "simd128"),
        target_arch = "x86_64"
    )))]
    [u16; 8],
);

impl Quad {
    /// Writes the low 16 bits of each lane of `lo`, then of `hi`, in lane
    /// order, to `group`'s eight steps (each lane a code, below 2^14).
    #[inline(always)]
    pub(crate) fn store_codes([lo, hi]: [Quad; 2], group: &mut [MaybeUninit<Step>]) {
        Codes8::narrow([lo, hi]).store(group);
    }
}

impl Codes8 {
    /// Columns to rows: `columns[i]` holds lane j's i-th value at lane j,
    /// row j holds them in order (an 8 x 8 transpose, by three rounds of
    /// interleaving halves: 16-bit, 32-bit and 64-bit lanes).
    #[inline(always)]
    pub(crate) fn transpose(columns: [Codes8; 8]) -> [Codes8; 8] {
        let [c0, c1, c2, c3, c4, c5, c6, c7] = columns;
        let t = [
            c0.low_16s(c1),
            c0.high_16s(c1),
            c2.low_16s(c3),
            c2.high_16s(c3),
            c4.low_16s(c5),
            c4.high_16s(c5),
            c6.low_16s(c7),
            c6.high_16s(c7),
        ];
        let u = [
            t[0].low_32s(t[2]),
            t[0].high_32s(t[2]),
            t[1].low_32s(t[3]),
            t[1].high_32s(t[3]),
            t[4].low_32s(t[6]),
            t[4].high_32s(t[6]),
            t[5].low_32s(t[7]),
            t[5].high_32s(t[7]),
        ];
        [
            u[0].low_64s(u[4]),
            u[0].high_64s(u[4]),
            u[1].low_64s(u[5]),
            u[1].high_64s(u[5]),
            u[2].low_64s(u[6]),
            u[2].high_64s(u[6]),
            u[3].low_64s(u[7]),
            u[3].high_64s(u[7]),
        ]
    }

    /// `a` where this lane's mask is 0, `b` where it is all ones.
    #[inline(always)]
    pub(crate) fn choose(self, a: Codes8, b: Codes8) -> Codes8 {
        a.xor(self.and(a.xor(b)))
    }
}

#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
impl Quad {
    #[inline(always)]
    pub(crate) fn new([a, b, c, d]: [i64; 4]) -> Quad {
        Quad(core::arch::wasm32::i32x4(
            a as i32, b as i32, c as i32, d as i32,
        ))
    }
    #[inline(always)]
    pub(crate) fn splat(x: i64) -> Quad {
        Quad(core::arch::wasm32::i32x4_splat(x as i32))
    }
    /// All ones in each lane whose value is above `limit`'s, else 0.
    #[inline(always)]
    pub(crate) fn above(self, limit: Quad) -> Quad {
        Quad(core::arch::wasm32::i32x4_gt(self.0, limit.0))
    }
    #[inline(always)]
    pub(crate) fn add(self, other: Quad) -> Quad {
        Quad(core::arch::wasm32::i32x4_add(self.0, other.0))
    }
    #[inline(always)]
    pub(crate) fn sub(self, other: Quad) -> Quad {
        Quad(core::arch::wasm32::i32x4_sub(self.0, other.0))
    }
    #[inline(always)]
    pub(crate) fn and(self, other: Quad) -> Quad {
        Quad(core::arch::wasm32::v128_and(self.0, other.0))
    }
    #[inline(always)]
    pub(crate) fn or(self, other: Quad) -> Quad {
        Quad(core::arch::wasm32::v128_or(self.0, other.0))
    }
    #[inline(always)]
    pub(crate) fn lanes(self) -> [i64; 4] {
        // SAFETY: v128 and [i32; 4] are both 16 plain bytes.
        unsafe { std::mem::transmute::<core::arch::wasm32::v128, [i32; 4]>(self.0) }.map(i64::from)
    }
}

#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
impl Codes8 {
    #[inline(always)]
    pub(crate) fn splat(x: u16) -> Codes8 {
        Codes8(core::arch::wasm32::u16x8_splat(x))
    }
    /// The lanes of `lo`, then of `hi`, narrowed to 16 bits with signed
    /// saturation (codes below 2^14 and masks of 0 or all ones keep their
    /// value).
    #[inline(always)]
    pub(crate) fn narrow([lo, hi]: [Quad; 2]) -> Codes8 {
        Codes8(core::arch::wasm32::i16x8_narrow_i32x4(lo.0, hi.0))
    }
    #[inline(always)]
    fn and(self, other: Codes8) -> Codes8 {
        Codes8(core::arch::wasm32::v128_and(self.0, other.0))
    }
    #[inline(always)]
    fn xor(self, other: Codes8) -> Codes8 {
        Codes8(core::arch::wasm32::v128_xor(self.0, other.0))
    }
    #[inline(always)]
    fn low_16s(self, other: Codes8) -> Codes8 {
        Codes8(core::arch::wasm32::u16x8_shuffle::<0, 8, 1, 9, 2, 10, 3, 11>(self.0, other.0))
    }
    #[inline(always)]
    fn high_16s(self, other: Codes8) -> Codes8 {
        Codes8(core::arch::wasm32::u16x8_shuffle::<
            4,
            12,
            5,
            13,
            6,
            14,
            7,
            15,
        >(self.0, other.0))
    }
    #[inline(always)]
    fn low_32s(self, other: Codes8) -> Codes8 {
        Codes8(core::arch::wasm32::u32x4_shuffle::<0, 4, 1, 5>(
            self.0, other.0,
        ))
    }
    #[inline(always)]
    fn high_32s(self, other: Codes8) -> Codes8 {
        Codes8(core::arch::wasm32::u32x4_shuffle::<2, 6, 3, 7>(
            self.0, other.0,
        ))
    }
    #[inline(always)]
    fn low_64s(self, other: Codes8) -> Codes8 {
        Codes8(core::arch::wasm32::u64x2_shuffle::<0, 2>(self.0, other.0))
    }
    #[inline(always)]
    fn high_64s(self, other: Codes8) -> Codes8 {
        Codes8(core::arch::wasm32::u64x2_shuffle::<1, 3>(self.0, other.0))
    }
    /// Writes the eight lanes to `group`'s eight steps, as 16 bytes.
    #[inline(always)]
    pub(crate) fn store(self, group: &mut [MaybeUninit<Step>]) {
        use core::arch::wasm32::{v128, v128_store};
        assert_eq!(group.len(), 8, "eight steps");
        // SAFETY: `group` is 8 slots of a Step, 16 bytes (Step is a u16),
        // borrowed mutably; a wasm store needs no alignment.
        unsafe { v128_store(group.as_mut_ptr().cast::<v128>(), self.0) }
    }
}

// SAFETY (every intrinsic below): SSE2 is part of x86-64 itself, so these
// instructions exist on every processor the target runs on.
#[cfg(target_arch = "x86_64")]
impl Quad {
    #[inline(always)]
    pub(crate) fn new([a, b, c, d]: [i64; 4]) -> Quad {
        Quad(unsafe { core::arch::x86_64::_mm_set_epi32(d as i32, c as i32, b as i32, a as i32) })
    }
    #[inline(always)]
    pub(crate) fn splat(x: i64) -> Quad {
        Quad(unsafe { core::arch::x86_64::_mm_set1_epi32(x as i32) })
    }
    /// All ones in each lane whose value is above `limit`'s, else 0.
    #[inline(always)]
    pub(crate) fn above(self, limit: Quad) -> Quad {
        Quad(unsafe { core::arch::x86_64::_mm_cmpgt_epi32(self.0, limit.0) })
    }
    #[inline(always)]
    pub(crate) fn add(self, other: Quad) -> Quad {
        Quad(unsafe { core::arch::x86_64::_mm_add_epi32(self.0, other.0) })
    }
    #[inline(always)]
    pub(crate) fn sub(self, other: Quad) -> Quad {
        Quad(unsafe { core::arch::x86_64::_mm_sub_epi32(self.0, other.0) })
    }
    #[inline(always)]
    pub(crate) fn and(self, other: Quad) -> Quad {
        Quad(unsafe { core::arch::x86_64::_mm_and_si128(self.0, other.0) })
    }
    #[inline(always)]
    pub(crate) fn or(self, other: Quad) -> Quad {
        Quad(unsafe { core::arch::x86_64::_mm_or_si128(self.0, other.0) })
    }
    #[inline(always)]
    pub(crate) fn lanes(self) -> [i64; 4] {
        // SAFETY: __m128i and [i32; 4] are both 16 plain bytes.
        unsafe { std::mem::transmute::<core::arch::x86_64::__m128i, [i32; 4]>(self.0) }
            .map(i64::from)
    }
}

#[cfg(target_arch = "x86_64")]
impl Codes8 {
    #[inline(always)]
    pub(crate) fn splat(x: u16) -> Codes8 {
        Codes8(unsafe { core::arch::x86_64::_mm_set1_epi16(x as i16) })
    }
    /// The lanes of `lo`, then of `hi`, narrowed to 16 bits with signed
    /// saturation (codes below 2^14 and masks of 0 or all ones keep their
    /// value).
    #[inline(always)]
    pub(crate) fn narrow([lo, hi]: [Quad; 2]) -> Codes8 {
        Codes8(unsafe { core::arch::x86_64::_mm_packs_epi32(lo.0, hi.0) })
    }
    #[inline(always)]
    fn and(self, other: Codes8) -> Codes8 {
        Codes8(unsafe { core::arch::x86_64::_mm_and_si128(self.0, other.0) })
    }
    #[inline(always)]
    fn xor(self, other: Codes8) -> Codes8 {
        Codes8(unsafe { core::arch::x86_64::_mm_xor_si128(self.0, other.0) })
    }
    #[inline(always)]
    fn low_16s(self, other: Codes8) -> Codes8 {
        Codes8(unsafe { core::arch::x86_64::_mm_unpacklo_epi16(self.0, other.0) })
    }
    #[inline(always)]
    fn high_16s(self, other: Codes8) -> Codes8 {
        Codes8(unsafe { core::arch::x86_64::_mm_unpackhi_epi16(self.0, other.0) })
    }
    #[inline(always)]
    fn low_32s(self, other: Codes8) -> Codes8 {
        Codes8(unsafe { core::arch::x86_64::_mm_unpacklo_epi32(self.0, other.0) })
    }
    #[inline(always)]
    fn high_32s(self, other: Codes8) -> Codes8 {
        Codes8(unsafe { core::arch::x86_64::_mm_unpackhi_epi32(self.0, other.0) })
    }
    #[inline(always)]
    fn low_64s(self, other: Codes8) -> Codes8 {
        Codes8(unsafe { core::arch::x86_64::_mm_unpacklo_epi64(self.0, other.0) })
    }
    #[inline(always)]
    fn high_64s(self, other: Codes8) -> Codes8 {
        Codes8(unsafe { core::arch::x86_64::_mm_unpackhi_epi64(self.0, other.0) })
    }
    /// Writes the eight lanes to `group`'s eight steps, as 16 bytes.
    #[inline(always)]
    pub(crate) fn store(self, group: &mut [MaybeUninit<Step>]) {
        use core::arch::x86_64::{__m128i, _mm_storeu_si128};
        assert_eq!(group.len(), 8, "eight steps");
        // SAFETY: `group` is 8 slots of a Step, 16 bytes (Step is a u16),
        // borrowed mutably; the store needs no alignment.
        unsafe { _mm_storeu_si128(group.as_mut_ptr().cast::<__m128i>(), self.0) }
    }
}

#[cfg(not(any(
    all(target_arch = "wasm32", target_feature = "simd128"),
    target_arch = "x86_64"
)))]
impl Quad {
    pub(crate) fn new(values: [i64; 4]) -> Quad {
        Quad(values.map(|v| v as i32))
    }
    pub(crate) fn splat(x: i64) -> Quad {
        Quad([x as i32; 4])
    }
    /// All ones in each lane whose value is above `limit`'s, else 0.
    pub(crate) fn above(self, limit: Quad) -> Quad {
        Quad([0, 1, 2, 3].map(|i| (limit.0[i] - self.0[i]) >> 31))
    }
    pub(crate) fn add(self, other: Quad) -> Quad {
        Quad([0, 1, 2, 3].map(|i| self.0[i] + other.0[i]))
    }
    pub(crate) fn sub(self, other: Quad) -> Quad {
        Quad([0, 1, 2, 3].map(|i| self.0[i] - other.0[i]))
    }
    pub(crate) fn and(self, other: Quad) -> Quad {
        Quad([0, 1, 2, 3].map(|i| self.0[i] & other.0[i]))
    }
    pub(crate) fn or(self, other: Quad) -> Quad {
        Quad([0, 1, 2, 3].map(|i| self.0[i] | other.0[i]))
    }
    pub(crate) fn lanes(self) -> [i64; 4] {
        self.0.map(i64::from)
    }
}

#[cfg(not(any(
    all(target_arch = "wasm32", target_feature = "simd128"),
    target_arch = "x86_64"
)))]
impl Codes8 {
    pub(crate) fn splat(x: u16) -> Codes8 {
        Codes8([x; 8])
    }
    /// The lanes of `lo`, then of `hi`, narrowed to 16 bits (codes below
    /// 2^14 and masks of 0 or all ones keep their value).
    pub(crate) fn narrow([lo, hi]: [Quad; 2]) -> Codes8 {
        Codes8(std::array::from_fn(|i| {
            (if i < 4 { lo.0[i] } else { hi.0[i - 4] }) as u16
        }))
    }
    fn and(self, other: Codes8) -> Codes8 {
        Codes8(std::array::from_fn(|i| self.0[i] & other.0[i]))
    }
    fn xor(self, other: Codes8) -> Codes8 {
        Codes8(std::array::from_fn(|i| self.0[i] ^ other.0[i]))
    }
    /// Lanes of `self` and `other` taken in turn, in runs of `run` lanes,
    /// from lane `from` on: the interleaving of each vector target's
    /// unpack instructions.
    fn interleave(self, other: Codes8, run: usize, from: usize) -> Codes8 {
        Codes8(std::array::from_fn(|i| {
            let (pair, within) = (i / (2 * run), i % (2 * run));
            let source = if within < run { self } else { other };
            source.0[from + pair * run + within % run]
        }))
    }
    fn low_16s(self, other: Codes8) -> Codes8 {
        self.interleave(other, 1, 0)
    }
    fn high_16s(self, other: Codes8) -> Codes8 {
        self.interleave(other, 1, 4)
    }
    fn low_32s(self, other: Codes8) -> Codes8 {
        self.interleave(other, 2, 0)
    }
    fn high_32s(self, other: Codes8) -> Codes8 {
        self.interleave(other, 2, 4)
    }
    fn low_64s(self, other: Codes8) -> Codes8 {
        self.interleave(other, 4, 0)
    }
    fn high_64s(self, other: Codes8) -> Codes8 {
        self.interleave(other, 4, 4)
    }
    /// Writes the eight lanes to `group`'s eight steps.
    pub(crate) fn store(self, group: &mut [MaybeUninit<Step>]) {
        assert_eq!(group.len(), 8, "eight steps");
        for (step, lane) in group.iter_mut().zip(self.0) {
            step.write(Step(lane));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn stored(codes: Codes8) -> [u16; 8] {
        let mut out = [MaybeUninit::uninit(); 8];
        codes.store(&mut out);
        // SAFETY: `store` wrote all eight.
        out.map(|s| unsafe { s.assume_init() }.0)
    }

    #[test]
    fn transpose_turns_columns_into_rows() {
        // Column i, lane j: 8·j + i, so row j reads 8·j .. 8·j + 8.
        let columns: [Codes8; 8] = std::array::from_fn(|i| {
            Codes8::narrow([
                Quad::new(std::array::from_fn(|j| (8 * j + i) as i64)),
                Quad::new(std::array::from_fn(|j| (8 * (j + 4) + i) as i64)),
            ])
        });
        for (j, row) in Codes8::transpose(columns).into_iter().enumerate() {
            assert_eq!(
                stored(row),
                std::array::from_fn(|i| (8 * j + i) as u16),
                "row {j}"
            );
        }
    }

    #[test]
    fn choose_takes_each_lane_by_its_mask() {
        let mask = Codes8::narrow([Quad::new([-1, 0, 0, -1]), Quad::new([0, -1, 0, 0])]);
        let chosen = mask.choose(Codes8::splat(0x0103), Codes8::splat(0x0007));
        assert_eq!(stored(chosen), [7, 0x103, 0x103, 7, 0x103, 7, 0x103, 0x103]);
    }
}
