//! Points from packed steps: the decode behind every bulk read of a
//! trace's points ([`crate::Trace::write_points`]).
//!
//! A point is the one before it plus its step's move on each axis. Taking
//! that move apart bit by bit costs several operations per axis per step
//! ([`crate::Point::apply`], which stays the reference the tests hold this
//! to); here, for 2 to 4 axes, a step's moving and negative bits index a
//! table of its moves per axis, padded to four lanes, so a step is one
//! table read and one four-wide addition (which the compiler may turn into
//! one vector instruction) whatever way the axes go. The number of axes is
//! a constant in each decode loop, so its loops over axes unroll, and four
//! steps' table indices come from one read of their codes
//! ([`table_indices_of_four`]: in wasm the 2D, 3D and 4D decodes of a
//! 2,000,001-point line 2.03 -> 1.42, 1.47 -> 1.22 and 1.76 -> 1.19 ms).
//!
//! The decode writes into memory that need not be initialised
//! (`MaybeUninit`): a new vector of points is then filled once, where a
//! zeroed one was written twice (the zeroing was a fifth of the native
//! end-to-end time of a 2,000,001-point 3D line, 0.55 of 2.3 ms).

use crate::grid::{MAX_AXES, Point, Step};
use std::mem::MaybeUninit;

/// A coordinate type points are written as: i64, as the core computes
/// them, or i32, what crosses to JavaScript (every trace coordinate is
/// within +-2^30: inputs are, and every arc is checked to stay within them).
pub trait Coordinate: Copy + Default + std::ops::AddAssign {
    fn from_i32(v: i32) -> Self;
    fn from_i64(v: i64) -> Self;
    fn to_i64(self) -> i64;

    /// [`decode`] on 2 axes: by the table, unless the type has a faster way.
    #[inline(always)]
    fn decode_pairs(start: &Point, steps: &[Step], out: &mut [MaybeUninit<Self>]) -> Point {
        by_table::<Self, 2, 16>(&MOVES_2, start, steps, out)
    }

    /// [`decode`] on 3 or 4 axes (`DIMS`) by `table`: [`by_table`], unless
    /// the type has a faster way.
    #[inline(always)]
    fn decode_rows<const DIMS: usize, const ENTRIES: usize>(
        table: &[[i32; 4]; ENTRIES],
        start: &Point,
        steps: &[Step],
        out: &mut [MaybeUninit<Self>],
    ) -> Point {
        by_table::<Self, DIMS, ENTRIES>(table, start, steps, out)
    }

    /// [`decode`] into memory that will not stay in cache until it is
    /// read (see [`decode_streaming`]): [`decode`] itself, unless the type
    /// has a way to write past the cache.
    #[inline(always)]
    fn decode_past_cache(start: &Point, steps: &[Step], out: &mut [MaybeUninit<Self>]) -> Point {
        decode(start, steps, out)
    }
}

impl Coordinate for i32 {
    #[inline(always)]
    fn from_i32(v: i32) -> i32 {
        v
    }
    #[inline(always)]
    fn from_i64(v: i64) -> i32 {
        debug_assert!(i32::try_from(v).is_ok(), "coordinate {v} past i32");
        v as i32
    }
    #[inline(always)]
    fn to_i64(self) -> i64 {
        self as i64
    }

    #[inline(always)]
    fn decode_pairs(start: &Point, steps: &[Step], out: &mut [MaybeUninit<i32>]) -> Point {
        by_pair_table::<false>(start, steps, out)
    }

    #[inline(always)]
    fn decode_rows<const DIMS: usize, const ENTRIES: usize>(
        table: &[[i32; 4]; ENTRIES],
        start: &Point,
        steps: &[Step],
        out: &mut [MaybeUninit<i32>],
    ) -> Point {
        by_vector_table::<DIMS, ENTRIES, false>(table, start, steps, out)
    }

    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    fn decode_past_cache(start: &Point, steps: &[Step], out: &mut [MaybeUninit<i32>]) -> Point {
        decode_streaming(start, steps, out)
    }
}

impl Coordinate for i64 {
    #[inline(always)]
    fn from_i32(v: i32) -> i64 {
        v as i64
    }
    #[inline(always)]
    fn from_i64(v: i64) -> i64 {
        v
    }
    #[inline(always)]
    fn to_i64(self) -> i64 {
        self
    }
}

/// The table index of a step on `dims` axes: its moving bits, then its
/// negative bits (bits 8.. of the code) right above them.
#[inline(always)]
const fn table_index(code: u16, dims: usize) -> usize {
    let mask = (1usize << dims) - 1;
    let code = code as usize;
    (code & mask) | ((code >> (8 - dims)) & (mask << dims))
}

/// [`table_index`] of four consecutive steps on `DIMS` axes (`ENTRIES` =
/// 4^DIMS), from their codes read as one u64: each code's negative bits
/// moved down beside its moving bits by one shift and one or for all four,
/// then each index one shift and one mask, where each code apart took a
/// load and five operations (in wasm the 3D decode's index arithmetic was
/// half its instructions). Exact because a step on DIMS axes has no bit of
/// a later axis: its bits DIMS..8 and 8 + DIMS.. are 0, so the or puts
/// nothing beside the negative bits, and what the shift brings down from
/// the next code lands above the index's 2·DIMS bits, which the mask drops.
#[inline(always)]
fn table_indices_of_four<const DIMS: usize, const ENTRIES: usize>(four: &[Step]) -> [usize; 4] {
    let joined = indices_in_place::<DIMS>(four);
    std::array::from_fn(|k| (joined >> (16 * k)) as usize & (ENTRIES - 1))
}

/// Four consecutive steps' codes on `DIMS` axes read as one u64, each
/// code's negative bits moved down beside its moving bits: code k's table
/// index in the low 2·DIMS bits of its 16 ([`table_indices_of_four`]).
#[inline(always)]
fn indices_in_place<const DIMS: usize>(four: &[Step]) -> u64 {
    debug_assert!(four.iter().all(|s| s.0 & !(((1 << DIMS) - 1) * 0x101) == 0));
    let codes = (four[0].0 as u64)
        | (four[1].0 as u64) << 16
        | (four[2].0 as u64) << 32
        | (four[3].0 as u64) << 48;
    codes | codes >> (8 - DIMS)
}

/// The [`PAIR_MOVES_2`] indices of four consecutive steps on 2 axes (the
/// first two, the last two): each code's four-bit index in the low bits of
/// its 16 ([`indices_in_place`]), and one more shift and or puts each odd
/// step's index above the even one's. Exact because above each index its
/// 16 bits hold only the code's negative bits (8 and 9) and the next
/// code's moving bits (brought down to 10 and 11), which the shift by 12
/// moves to bits 0 to 3 of the 16 before, past the pair's mask, or to bits
/// the mask drops.
#[inline(always)]
fn pair_indices_of_four(four: &[Step]) -> [usize; 2] {
    let joined = indices_in_place::<2>(four);
    let pairs = joined | joined >> 12;
    [pairs as usize & 255, (pairs >> 32) as usize & 255]
}

/// Per table index of a step on `DIMS` axes (4^DIMS of them, `ENTRIES`),
/// its move per axis, as [`Step::delta`] gives it (a negative bit without
/// its moving bit moves nothing), padded with zeros to four lanes.
const fn move_table<const DIMS: usize, const ENTRIES: usize>() -> [[i32; 4]; ENTRIES] {
    assert!(ENTRIES == 1 << (2 * DIMS) && DIMS <= 4);
    let mut table = [[0; 4]; ENTRIES];
    let mut index = 0;
    while index < ENTRIES {
        let mut axis = 0;
        while axis < DIMS {
            let moved = (index >> axis & 1) as i32;
            let negative = (index >> (DIMS + axis) & 1) as i32;
            table[index][axis] = moved - 2 * (moved & negative);
            axis += 1;
        }
        index += 1;
    }
    table
}

static MOVES_2: [[i32; 4]; 16] = move_table::<2, 16>();

/// Per two consecutive steps on 2 axes, indexed by the first's table index
/// plus 16 times the second's ([`pair_indices_of_four`]), the moves from
/// the point before them to the point after each: [dx0, dy0, dx0 + dx1,
/// dy0 + dy1], the two rows they write less the point before them
/// ([`by_pair_table`]). 4 KiB.
static PAIR_MOVES_2: [[i32; 4]; 256] = {
    let mut pairs = [[0; 4]; 256];
    let mut index = 0;
    while index < 256 {
        let (first, second) = (MOVES_2[index & 15], MOVES_2[index >> 4]);
        pairs[index] = [
            first[0],
            first[1],
            first[0] + second[0],
            first[1] + second[1],
        ];
        index += 1;
    }
    pairs
};
static MOVES_3: [[i32; 4]; 64] = move_table::<3, 64>();
static MOVES_4: [[i32; 4]; 256] = move_table::<4, 256>();

/// Writes the point after each of `steps`, taken from `start`, into `out`
/// (stride `start.dims()`, `out.len()` = that times `steps.len()`), and
/// returns the last (`start` when there are no steps). Every value of
/// `out` is written.
pub fn decode<C: Coordinate>(start: &Point, steps: &[Step], out: &mut [MaybeUninit<C>]) -> Point {
    assert_eq!(out.len(), steps.len() * start.dims(), "one row per step");
    match start.dims() {
        2 => C::decode_pairs(start, steps, out),
        3 => C::decode_rows::<3, 64>(&MOVES_3, start, steps, out),
        4 => C::decode_rows::<4, 256>(&MOVES_4, start, steps, out),
        1 => by_bits::<C, 1>(start, steps, out),
        5 => by_bits::<C, 5>(start, steps, out),
        _ => by_bits::<C, MAX_AXES>(start, steps, out),
    }
}

/// Bytes of points from which [`decode_to_new`] writes them past the
/// cache: more than a core's L2 cache holds (1 MiB on the AMD EPYC, 2 MiB
/// on the Intel Xeon the benches ran on), and than the share of L3 one core
/// can count on, so that the first points written are gone from the cache
/// by the time the last are, and a reader fetches them from memory either
/// way.
const PAST_CACHE_BYTES: usize = 8 << 20;

/// [`decode`] into a new array that the caller hands over whole (a
/// trace's points read at once, [`crate::Trace::points_i32`]): past
/// [`PAST_CACHE_BYTES`], by [`Coordinate::decode_past_cache`].
pub fn decode_to_new<C: Coordinate>(
    start: &Point,
    steps: &[Step],
    out: &mut [MaybeUninit<C>],
) -> Point {
    if std::mem::size_of_val(out) < PAST_CACHE_BYTES {
        decode(start, steps, out)
    } else {
        C::decode_past_cache(start, steps, out)
    }
}

/// [`decode`] into i32 with its vector stores past the cache (x86-64's
/// non-temporal stores). An ordinary store into memory not in cache first
/// reads the line it writes into (its old bytes, never used), so points
/// too many to stay in cache cost twice their bytes of memory traffic; a
/// streaming store sends its line straight to memory. Natively the points
/// of the bench's 2,000,001-point 3D line (24 MB) took 3.65 to 3.88 ms with
/// the trace, 2.99 to 3.03 ms so (Intel Xeon, `end_to_end` example, four
/// runs alternating the two).
///
/// Such a store needs a 16-byte aligned place: the rows before the first
/// that starts on one (three at most) are decoded as usual, and when no
/// row does (an even number of axes from an address 4 past a multiple of
/// 8), all of them.
#[cfg(target_arch = "x86_64")]
fn decode_streaming(start: &Point, steps: &[Step], out: &mut [MaybeUninit<i32>]) -> Point {
    let dims = start.dims();
    let row_bytes = dims * std::mem::size_of::<i32>();
    let aligned = (0..4).find(|rows| (out.as_ptr() as usize + rows * row_bytes) % 16 == 0);
    let (2..=4, Some(head)) = (dims, aligned) else {
        return decode(start, steps, out);
    };
    let head = head.min(steps.len());
    let (head_out, rest) = out.split_at_mut(head * dims);
    let p = decode(start, &steps[..head], head_out);
    let steps = &steps[head..];
    let end = match dims {
        2 => by_pair_table::<true>(&p, steps, rest),
        3 => by_vector_table::<3, 64, true>(&MOVES_3, &p, steps, rest),
        _ => by_vector_table::<4, 256, true>(&MOVES_4, &p, steps, rest),
    };
    // Streaming stores are weakly ordered, even with this thread's later
    // reads: the fence orders them before any read of the points.
    // SAFETY: SSE is part of x86-64 itself.
    unsafe { core::arch::x86_64::_mm_sfence() };
    end
}

/// [`decode`] for 2 to 4 axes: one table read and a four-lane add per step.
#[inline(always)]
fn by_table<C: Coordinate, const DIMS: usize, const ENTRIES: usize>(
    table: &[[i32; 4]; ENTRIES],
    start: &Point,
    steps: &[Step],
    out: &mut [MaybeUninit<C>],
) -> Point {
    let mut p = [C::default(); 4];
    for axis in 0..DIMS {
        p[axis] = C::from_i64(start.get(axis));
    }
    // Every row but the last is written with all four lanes, the lanes
    // past DIMS landing on the next row's first values, which that row's
    // write then replaces: one four-wide store instead of DIMS narrow ones.
    let Some((last, body)) = steps.split_last() else {
        return *start;
    };
    assert!(DIMS >= 2 && out.len() == steps.len() * DIMS);
    let base = out.as_mut_ptr().cast::<C>();
    for (k, step) in body.iter().enumerate() {
        let moves = &table[table_index(step.0, DIMS)];
        for lane in 0..4 {
            p[lane] += C::from_i32(moves[lane]);
        }
        // SAFETY: k <= steps.len() - 2, so row k's four lanes end at
        // k·DIMS + 4 <= steps.len()·DIMS = out.len() (DIMS >= 2, asserted
        // above); `out` is borrowed mutably and not otherwise touched here.
        unsafe { base.add(k * DIMS).cast::<[C; 4]>().write_unaligned(p) };
    }
    let moves = &table[table_index(last.0, DIMS)];
    for lane in 0..4 {
        p[lane] += C::from_i32(moves[lane]);
    }
    // The last row's DIMS lanes, copied through `base` as the rows above
    // are written: with an iterator over `out` here instead, LLVM kept `p`
    // on the stack through the loop above, and each row's store waited on
    // a failed store forward (the native decode of a 3D line took 7 times
    // as long). SAFETY: that row's DIMS values end at out.len().
    unsafe { std::ptr::copy_nonoverlapping(p.as_ptr(), base.add(body.len() * DIMS), DIMS) };
    end_point(start, &p[..DIMS])
}

/// [`by_table`] into i32, the point one 128-bit vector ([`Lanes4`]): a
/// step is one table read, one vector add and one 16-byte store. Written
/// as [`by_table`]'s plain arrays, LLVM split the add into two lanes and
/// one, and the store into three (the fourth lane known to stay 0): three
/// stores a row, where the store port was the loop's limit (the native
/// decode of a 3D line took 1.8 ms for its 2,000,001 points, where a
/// memset of their 24 MB takes 0.7). On 3 axes four rows are 12 values,
/// three whole vectors ([`Lanes4::rows_of_three`]): three stores for four
/// steps, none straddling another's bytes (1.39 ms to 1.30 ms natively).
///
/// With `STREAMING`, the vectors of whole rows (four rows at a time on 3
/// axes) go past the cache ([`Lanes4::store_as`]): `out` must then start
/// 16-byte aligned ([`decode_streaming`]).
#[inline(always)]
fn by_vector_table<const DIMS: usize, const ENTRIES: usize, const STREAMING: bool>(
    table: &[[i32; 4]; ENTRIES],
    start: &Point,
    steps: &[Step],
    out: &mut [MaybeUninit<i32>],
) -> Point {
    assert!(DIMS >= 2 && DIMS <= 4 && out.len() == steps.len() * DIMS);
    let mut first = [0; 4];
    for (axis, c) in first.iter_mut().enumerate().take(DIMS) {
        *c = i32::from_i64(start.get(axis));
    }
    // Lanes past DIMS stay 0: the start's are, and so are the table's.
    let mut p = Lanes4::load(&first);
    let base = out.as_mut_ptr().cast::<i32>();
    let moved_by = |p: Lanes4, index: usize| p.add(Lanes4::load(&table[index]));
    let moved = |p: Lanes4, step: &Step| moved_by(p, table_index(step.0, DIMS));
    let mut rows = 0;
    if DIMS == 3 {
        for four in steps.chunks_exact(4) {
            let [i0, i1, i2, i3] = table_indices_of_four::<DIMS, ENTRIES>(four);
            let p0 = moved_by(p, i0);
            let p1 = moved_by(p0, i1);
            let p2 = moved_by(p1, i2);
            p = moved_by(p2, i3);
            for (i, vector) in Lanes4::rows_of_three([p0, p1, p2, p])
                .into_iter()
                .enumerate()
            {
                // SAFETY: rows `rows..rows + 4` are values rows·3 .. rows·3
                // + 12 <= out.len() (four more steps are left); with
                // STREAMING, `base` is 16-byte aligned and so is every
                // vector's place, 48 bytes a four rows.
                unsafe { vector.store_as::<STREAMING>(base.add(rows * 3 + 4 * i)) };
            }
            rows += 4;
        }
    } else if DIMS == 4 {
        // A row is one whole vector.
        for four in steps.chunks_exact(4) {
            for index in table_indices_of_four::<DIMS, ENTRIES>(four) {
                p = moved_by(p, index);
                // SAFETY: four more steps are left, so row `rows`' four
                // values end at (rows + 1)·4 <= out.len(); with STREAMING,
                // `base` and so every row is 16-byte aligned.
                unsafe { p.store_as::<STREAMING>(base.add(rows * 4)) };
                rows += 1;
            }
        }
    }
    let Some((last, body)) = steps[rows..].split_last() else {
        return end_point(start, &p.to_array()[..DIMS]);
    };
    for step in body {
        p = moved(p, step);
        // SAFETY: as in by_table, the row's four lanes end at rows·DIMS + 4
        // <= out.len() for every row but the last; the lanes past DIMS land
        // on the next row, which its own store then replaces.
        unsafe { p.store(base.add(rows * DIMS)) };
        rows += 1;
    }
    let p = moved(p, last).to_array();
    // SAFETY: the last row's DIMS values end at out.len().
    unsafe { std::ptr::copy_nonoverlapping(p.as_ptr(), base.add(rows * DIMS), DIMS) };
    end_point(start, &p[..DIMS])
}

/// Four i32 lanes in one 128-bit vector where the target has one (x86-64,
/// whose every processor has SSE2; wasm with SIMD), else plain lanes.
#[derive(Clone, Copy)]
struct Lanes4(
    #[cfg(target_arch = "x86_64")] core::arch::x86_64::__m128i,
    #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))] core::arch::wasm32::v128,
    #[cfg(not(any(
        target_arch = "x86_64",
        all(target_arch = "wasm32", target_feature = "simd128")
    )))]
    [i32; 4],
);

impl Lanes4 {
    /// Writes the four lanes to `at..at + 4`, with `STREAMING` past the
    /// cache where the target can ([`decode_streaming`]: x86-64), else as
    /// [`Lanes4::store`] does.
    /// SAFETY: the caller owns those 16 bytes; with `STREAMING` on x86-64,
    /// `at` is 16-byte aligned.
    #[inline(always)]
    unsafe fn store_as<const STREAMING: bool>(self, at: *mut i32) {
        #[cfg(target_arch = "x86_64")]
        if STREAMING {
            use core::arch::x86_64::{__m128i, _mm_stream_si128};
            unsafe { _mm_stream_si128(at.cast::<__m128i>(), self.0) };
            return;
        }
        unsafe { self.store(at) }
    }
}

// SAFETY (the intrinsics): SSE2 is part of x86-64 itself; the unaligned
// load reads the 16 bytes of a [i32; 4].
#[cfg(target_arch = "x86_64")]
impl Lanes4 {
    #[inline(always)]
    fn load(values: &[i32; 4]) -> Lanes4 {
        use core::arch::x86_64::{__m128i, _mm_loadu_si128};
        Lanes4(unsafe { _mm_loadu_si128(values.as_ptr().cast::<__m128i>()) })
    }
    #[inline(always)]
    fn add(self, other: Lanes4) -> Lanes4 {
        Lanes4(unsafe { core::arch::x86_64::_mm_add_epi32(self.0, other.0) })
    }
    /// Lanes 2 and 3, twice: [a2, a3, a2, a3].
    #[inline(always)]
    fn high_pair(self) -> Lanes4 {
        Lanes4(unsafe { core::arch::x86_64::_mm_shuffle_epi32::<0xEE>(self.0) })
    }
    /// Four points of 3 axes (lane 3 of each 0) as their 12 values, in
    /// three vectors: [x0 y0 z0 x1], [y1 z1 x2 y2], [z2 x3 y3 z3], each two
    /// points' lanes shifted into place and joined (the zero lane makes an
    /// or a join).
    #[inline(always)]
    fn rows_of_three([p0, p1, p2, p3]: [Lanes4; 4]) -> [Lanes4; 3] {
        use core::arch::x86_64::{_mm_or_si128, _mm_slli_si128, _mm_srli_si128};
        unsafe {
            [
                Lanes4(_mm_or_si128(p0.0, _mm_slli_si128::<12>(p1.0))),
                Lanes4(_mm_or_si128(
                    _mm_srli_si128::<4>(p1.0),
                    _mm_slli_si128::<8>(p2.0),
                )),
                Lanes4(_mm_or_si128(
                    _mm_srli_si128::<8>(p2.0),
                    _mm_slli_si128::<4>(p3.0),
                )),
            ]
        }
    }
    /// Writes the four lanes to `at..at + 4`, unaligned.
    /// SAFETY: the caller owns those 16 bytes.
    #[inline(always)]
    unsafe fn store(self, at: *mut i32) {
        use core::arch::x86_64::{__m128i, _mm_storeu_si128};
        unsafe { _mm_storeu_si128(at.cast::<__m128i>(), self.0) }
    }
    #[inline(always)]
    fn to_array(self) -> [i32; 4] {
        // SAFETY: __m128i and [i32; 4] are both 16 plain bytes.
        unsafe { std::mem::transmute::<core::arch::x86_64::__m128i, [i32; 4]>(self.0) }
    }
}

// SAFETY (the loads and stores): as on x86-64, 16 bytes of a [i32; 4] or
// owned by the caller, unaligned (wasm's v128 accesses need no alignment).
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
impl Lanes4 {
    #[inline(always)]
    fn load(values: &[i32; 4]) -> Lanes4 {
        use core::arch::wasm32::{v128, v128_load};
        Lanes4(unsafe { v128_load(values.as_ptr().cast::<v128>()) })
    }
    #[inline(always)]
    fn add(self, other: Lanes4) -> Lanes4 {
        Lanes4(core::arch::wasm32::i32x4_add(self.0, other.0))
    }
    /// Lanes 2 and 3, twice: [a2, a3, a2, a3].
    #[inline(always)]
    fn high_pair(self) -> Lanes4 {
        Lanes4(core::arch::wasm32::i32x4_shuffle::<2, 3, 2, 3>(
            self.0, self.0,
        ))
    }
    /// Four points of 3 axes as their 12 values, in three vectors: [x0 y0
    /// z0 x1], [y1 z1 x2 y2], [z2 x3 y3 z3], each a shuffle of two points.
    #[inline(always)]
    fn rows_of_three([p0, p1, p2, p3]: [Lanes4; 4]) -> [Lanes4; 3] {
        use core::arch::wasm32::i32x4_shuffle;
        [
            Lanes4(i32x4_shuffle::<0, 1, 2, 4>(p0.0, p1.0)),
            Lanes4(i32x4_shuffle::<1, 2, 4, 5>(p1.0, p2.0)),
            Lanes4(i32x4_shuffle::<2, 4, 5, 6>(p2.0, p3.0)),
        ]
    }
    /// Writes the four lanes to `at..at + 4`.
    /// SAFETY: the caller owns those 16 bytes.
    #[inline(always)]
    unsafe fn store(self, at: *mut i32) {
        use core::arch::wasm32::{v128, v128_store};
        unsafe { v128_store(at.cast::<v128>(), self.0) }
    }
    #[inline(always)]
    fn to_array(self) -> [i32; 4] {
        // SAFETY: v128 and [i32; 4] are both 16 plain bytes.
        unsafe { std::mem::transmute::<core::arch::wasm32::v128, [i32; 4]>(self.0) }
    }
}

#[cfg(not(any(
    target_arch = "x86_64",
    all(target_arch = "wasm32", target_feature = "simd128")
)))]
impl Lanes4 {
    fn load(values: &[i32; 4]) -> Lanes4 {
        Lanes4(*values)
    }
    fn add(self, other: Lanes4) -> Lanes4 {
        Lanes4([0, 1, 2, 3].map(|i| self.0[i] + other.0[i]))
    }
    /// Lanes 2 and 3, twice: [a2, a3, a2, a3].
    fn high_pair(self) -> Lanes4 {
        Lanes4([self.0[2], self.0[3], self.0[2], self.0[3]])
    }
    /// Four points of 3 axes as their 12 values, in three vectors.
    fn rows_of_three(points: [Lanes4; 4]) -> [Lanes4; 3] {
        let mut values = [0; 12];
        for (row, p) in values.chunks_exact_mut(3).zip(points) {
            row.copy_from_slice(&p.0[..3]);
        }
        [0, 1, 2].map(|i| Lanes4(std::array::from_fn(|lane| values[4 * i + lane])))
    }
    /// SAFETY: the caller owns the 16 bytes at `at`.
    unsafe fn store(self, at: *mut i32) {
        unsafe { at.cast::<[i32; 4]>().write_unaligned(self.0) }
    }
    fn to_array(self) -> [i32; 4] {
        self.0
    }
}

/// [`decode`] on 2 axes into i32, two steps at a time: the point twice
/// in one 128-bit vector ([`Lanes4`]: x, y, x, y), to which one read of
/// [`PAIR_MOVES_2`] adds the moves to both rows, written in one 16-byte
/// store. The point after them is the sum's high pair repeated; for four
/// steps that is the point plus the first pair's high half plus the second
/// pair's, so the chain from four steps to the next is two adds, and the
/// rest (two table reads, two adds, two shuffles, two stores) runs beside
/// it. A step a read, the point one u64 with x and y offset by 2^31 in its
/// halves (one add and one flip of their top bits a row), took half as many
/// instructions again: the points of a 2,000,001-point 2D line decoded in
/// 1.06 to 1.08 ms natively, 0.63 ms so; read in Node, 2.5 to 2.6 ms,
/// 2.0 to 2.1 ms so.
///
/// With `STREAMING`, the stores of each four steps go past the cache
/// ([`Lanes4::store_as`]): `out` must then start 16-byte aligned.
#[inline(always)]
fn by_pair_table<const STREAMING: bool>(
    start: &Point,
    steps: &[Step],
    out: &mut [MaybeUninit<i32>],
) -> Point {
    assert!(start.dims() == 2 && out.len() == steps.len() * 2);
    let (x, y) = (i32::from_i64(start.get(0)), i32::from_i64(start.get(1)));
    let mut p = Lanes4::load(&[x, y, x, y]);
    let base = out.as_mut_ptr().cast::<i32>();
    let fours = steps.chunks_exact(4);
    let rest = fours.remainder();
    let mut rows = 0;
    for four in fours {
        let [first, second] = pair_indices_of_four(four).map(|i| Lanes4::load(&PAIR_MOVES_2[i]));
        let after_first = p.add(first.high_pair());
        // SAFETY: four more steps are left, so rows `rows..rows + 4`, the
        // values rows·2 .. rows·2 + 8, lie within `out`; with STREAMING,
        // `base` and so both 16-byte halves are 16-byte aligned.
        unsafe {
            p.add(first).store_as::<STREAMING>(base.add(rows * 2));
            after_first
                .add(second)
                .store_as::<STREAMING>(base.add(rows * 2 + 4));
        }
        p = after_first.add(second.high_pair());
        rows += 4;
    }
    let [mut x, mut y, _, _] = p.to_array();
    for (step, row) in rest.iter().zip(out[rows * 2..].chunks_exact_mut(2)) {
        let moves = MOVES_2[table_index(step.0, 2)];
        (x, y) = (x + moves[0], y + moves[1]);
        row[0].write(x);
        row[1].write(y);
    }
    end_point(start, &[x, y])
}

/// `start` moved to `coords`.
#[inline(always)]
fn end_point<C: Coordinate>(start: &Point, coords: &[C]) -> Point {
    let mut end = *start;
    for (c, &v) in end.coords_mut().iter_mut().zip(coords) {
        *c = v.to_i64();
    }
    end
}

/// [`decode`] for 1, 5 or 6 axes (a table would have 4^6 entries): each
/// axis's move from its two bits ([`Step::delta`]).
#[inline(always)]
fn by_bits<C: Coordinate, const DIMS: usize>(
    start: &Point,
    steps: &[Step],
    out: &mut [MaybeUninit<C>],
) -> Point {
    let mut p = [C::default(); DIMS];
    for axis in 0..DIMS {
        p[axis] = C::from_i64(start.get(axis));
    }
    for (step, row) in steps.iter().zip(out.chunks_exact_mut(DIMS)) {
        for axis in 0..DIMS {
            p[axis] += C::from_i64(step.delta(axis));
        }
        for (c, &v) in row.iter_mut().zip(&p) {
            c.write(v);
        }
    }
    end_point(start, &p)
}

/// The smallest and the largest coordinate on each axis over `start` and
/// the point after each of `steps` (the box every point of the path lies
/// in), and the last of those points. The same moves as [`decode`] (a
/// table read per step for 2 to 4 axes), kept in registers rather than
/// written out.
pub fn bounds(start: &Point, steps: &[Step]) -> (Point, Point, Point) {
    match start.dims() {
        2 => bounds_by_table::<2, 16>(&MOVES_2, start, steps),
        3 => bounds_by_table::<3, 64>(&MOVES_3, start, steps),
        4 => bounds_by_table::<4, 256>(&MOVES_4, start, steps),
        1 => bounds_by_bits::<1>(start, steps),
        5 => bounds_by_bits::<5>(start, steps),
        _ => bounds_by_bits::<MAX_AXES>(start, steps),
    }
}

/// Whether each axis moves one way only over `steps`, or not at all: then
/// the path's extremes on each axis are at its two ends. An OR of every
/// code, a few operations a step, where [`bounds`] takes a table read and
/// a min and max per axis.
pub fn one_way(steps: &[Step]) -> bool {
    let (mut forward, mut backward) = (0u16, 0u16);
    for step in steps {
        // Bit 8 + a: axis a's move is negative (read only where bit a moves).
        let negative = step.0 >> 8;
        forward |= step.0 & !negative;
        backward |= step.0 & negative;
    }
    forward & backward & 0xFF == 0
}

/// [`bounds`] for 2 to 4 axes: one table read, then an add, a min and a
/// max on each axis per step.
#[inline(always)]
fn bounds_by_table<const DIMS: usize, const ENTRIES: usize>(
    table: &[[i32; 4]; ENTRIES],
    start: &Point,
    steps: &[Step],
) -> (Point, Point, Point) {
    bounds_by_move::<DIMS>(start, steps, |step, axis| {
        table[table_index(step.0, DIMS)][axis] as i64
    })
}

/// [`bounds`] for 1, 5 or 6 axes: each axis's move from its two bits.
#[inline(always)]
fn bounds_by_bits<const DIMS: usize>(start: &Point, steps: &[Step]) -> (Point, Point, Point) {
    bounds_by_move::<DIMS>(start, steps, |step, axis| step.delta(axis))
}

/// [`bounds`] with the move of a step on an axis given by
/// `move_on(step, axis)`: an add, a min and a max on each axis per step.
#[inline(always)]
fn bounds_by_move<const DIMS: usize>(
    start: &Point,
    steps: &[Step],
    move_on: impl Fn(Step, usize) -> i64,
) -> (Point, Point, Point) {
    let mut p = [0i64; DIMS];
    p.copy_from_slice(start.coords());
    let (mut low, mut high) = (p, p);
    for &step in steps {
        for axis in 0..DIMS {
            p[axis] += move_on(step, axis);
            low[axis] = low[axis].min(p[axis]);
            high[axis] = high[axis].max(p[axis]);
        }
    }
    (
        end_point(start, &low),
        end_point(start, &high),
        end_point(start, &p),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`decode`] into memory already initialised, as the tests read it.
    fn decode_into<C: Coordinate>(start: &Point, steps: &[Step], out: &mut [C]) -> Point {
        // SAFETY: MaybeUninit<C> has C's layout, and `decode` writes only
        // initialised values of C, so `out` holds valid values throughout.
        let out = unsafe { &mut *(out as *mut [C] as *mut [MaybeUninit<C>]) };
        decode(start, steps, out)
    }

    /// Every code a step on `dims` axes can have, with stray negative bits
    /// (on axes that do not move) included.
    fn every_code(dims: usize) -> impl Iterator<Item = Step> {
        let mask = (1u16 << dims) - 1;
        (0..1u16 << (2 * dims)).map(move |i| Step((i & mask) | (i >> dims & mask) << 8))
    }

    /// Every code at each of the four places of a group of four steps (the
    /// decodes read four codes at once: [`table_indices_of_four`]), the
    /// steps ending at each place too: `lead` steps of one move first.
    #[test]
    fn every_step_code_moves_as_apply_does() {
        for (dims, lead) in (1..=MAX_AXES).flat_map(|dims| (0..4).map(move |lead| (dims, lead))) {
            let start = Point::new(&[-(1 << 30), 5, 1 << 30, 0, -7, 3][..dims]);
            let mut steps = vec![Step(0x101); lead];
            steps.extend(every_code(dims));
            let mut out = vec![0i64; steps.len() * dims];
            let end = decode_into(&start, &steps, &mut out);
            let mut narrow = vec![0i32; steps.len() * dims];
            decode_into(&start, &steps, &mut narrow);
            let mut p = start;
            for (k, step) in steps.iter().enumerate() {
                p.apply(*step);
                assert_eq!(
                    &out[k * dims..(k + 1) * dims],
                    p.coords(),
                    "{dims} axes, {lead} steps first, {step:?}"
                );
                let wide: Vec<i64> = narrow[k * dims..(k + 1) * dims]
                    .iter()
                    .map(|&c| c as i64)
                    .collect();
                assert_eq!(wide, p.coords());
            }
            assert_eq!(end, p);
        }
    }

    /// The planar decode reads two steps' moves at once ([`PAIR_MOVES_2`]):
    /// every ordered pair of codes, at each place of a group of four.
    #[test]
    fn every_pair_of_planar_codes_moves_as_apply_does() {
        let codes: Vec<Step> = every_code(2).collect();
        for lead in 0..4 {
            let start = Point::new(&[-(1 << 30) + 3, (1 << 30) - 3]);
            let mut steps = vec![Step(0x101); lead];
            for a in &codes {
                for b in &codes {
                    steps.extend([*a, *b]);
                }
            }
            let mut out = vec![0i32; steps.len() * 2];
            let end = decode_into(&start, &steps, &mut out);
            let mut p = start;
            for (k, step) in steps.iter().enumerate() {
                p.apply(*step);
                let row = [out[2 * k] as i64, out[2 * k + 1] as i64];
                assert_eq!(
                    &row[..],
                    p.coords(),
                    "{lead} steps first, step {k}: {step:?}"
                );
            }
            assert_eq!(end, p);
        }
    }

    /// The streaming decode, whatever the alignment of its output and
    /// however many steps (fewer than its aligned head, a group of four
    /// and a tail), writes what [`decode`] does.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn the_streaming_decode_writes_what_decode_does_at_every_alignment() {
        for dims in 1..=MAX_AXES {
            let start = Point::new(&[-(1 << 30), 5, 1 << 30, 0, -7, 3][..dims]);
            let every: Vec<Step> = every_code(dims).chain(every_code(dims).skip(1)).collect();
            for len in (0..12.min(every.len())).chain([every.len() - 1, every.len()]) {
                let steps = &every[..len];
                let mut want = vec![0i32; len * dims];
                let want_end = decode_into(&start, steps, &mut want);
                // A u128 vector is 16-byte aligned: `offset` values into it
                // is each alignment an i32 can have.
                let mut memory = vec![0u128; (len * dims).div_ceil(4) + 1];
                for offset in 0..4 {
                    // SAFETY: u128 is 16 bytes of four i32 lanes; the slice
                    // lies within `memory`, which it borrows mutably.
                    let out = unsafe {
                        std::slice::from_raw_parts_mut(
                            memory.as_mut_ptr().cast::<MaybeUninit<i32>>().add(offset),
                            len * dims,
                        )
                    };
                    let end = decode_streaming(&start, steps, out);
                    // SAFETY: decode_streaming wrote every value of `out`.
                    let got = unsafe { &*(out as *const [MaybeUninit<i32>] as *const [i32]) };
                    assert_eq!(
                        got,
                        &want[..],
                        "{dims} axes, {len} steps, {offset} values in"
                    );
                    assert_eq!(
                        end, want_end,
                        "{dims} axes, {len} steps, {offset} values in"
                    );
                }
            }
        }
    }

    #[test]
    fn one_way_is_whether_no_axis_moves_both_ways() {
        for dims in 1..=MAX_AXES {
            let codes: Vec<Step> = every_code(dims).collect();
            for a in &codes {
                for b in &codes {
                    let both_ways = (0..dims).any(|axis| a.delta(axis) * b.delta(axis) < 0);
                    assert_eq!(
                        one_way(&[*a, *b]),
                        !both_ways,
                        "{dims} axes, {a:?} then {b:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn bounds_are_the_extremes_of_the_points_apply_gives() {
        for dims in 1..=MAX_AXES {
            let start = Point::new(&[-(1 << 30), 5, 1 << 30, 0, -7, 3][..dims]);
            // Every code, then every code again in reverse: each axis goes
            // both ways, so each bound is met in the middle of the path.
            let mut steps: Vec<Step> = every_code(dims).collect();
            steps.extend(every_code(dims).collect::<Vec<_>>().into_iter().rev());
            for len in [0, 1, steps.len() / 3, steps.len()] {
                let (low, high, end) = bounds(&start, &steps[..len]);
                let mut p = start;
                let (mut want_low, mut want_high) =
                    (start.coords().to_vec(), start.coords().to_vec());
                for step in &steps[..len] {
                    p.apply(*step);
                    for (axis, &c) in p.coords().iter().enumerate() {
                        want_low[axis] = want_low[axis].min(c);
                        want_high[axis] = want_high[axis].max(c);
                    }
                }
                assert_eq!(end, p, "{dims} axes, {len} steps");
                assert_eq!(low.coords(), &want_low[..], "{dims} axes, {len} steps");
                assert_eq!(high.coords(), &want_high[..], "{dims} axes, {len} steps");
            }
        }
    }
}
