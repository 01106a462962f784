//! How much heap the core holds, so that a long run stops cleanly before
//! memory runs out. A wasm32 instance has at most 4 GiB; an allocation past
//! it aborts with a trap (`RuntimeError: unreachable`) that leaves the
//! instance's objects borrowed, so no caller could recover or even free
//! what it holds. Counting every allocation costs one relaxed add.

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

/// What a G-code run may see held before it stops: 2 GiB, half of wasm32's
/// 4 GiB. The rest is for the allocator's slack and the run's vectors, which
/// double as they grow (the trace's segments and steps, the move records):
/// one doubling of a vector holding a fifth of the heap needs 40% more for
/// a moment, and what a caller then reads of the result needs room too.
pub const HEAP_BUDGET_BYTES: usize = 2 << 30;

static HELD_BYTES: AtomicUsize = AtomicUsize::new(0);

/// The system allocator, counting the bytes it holds.
struct Counting;

// SAFETY: every call is passed to `System` unchanged; only the count is added.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            HELD_BYTES.fetch_add(layout.size(), Ordering::Relaxed);
        }
        p
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        let p = unsafe { System.alloc_zeroed(layout) };
        if !p.is_null() {
            HELD_BYTES.fetch_add(layout.size(), Ordering::Relaxed);
        }
        p
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) };
        HELD_BYTES.fetch_sub(layout.size(), Ordering::Relaxed);
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let p = unsafe { System.realloc(ptr, layout, new_size) };
        if !p.is_null() {
            HELD_BYTES.fetch_add(new_size, Ordering::Relaxed);
            HELD_BYTES.fetch_sub(layout.size(), Ordering::Relaxed);
        }
        p
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// Bytes of heap held now, by everything in this process (or wasm instance).
pub fn held_bytes() -> usize {
    HELD_BYTES.load(Ordering::Relaxed)
}

/// Makes room in `v` for exactly `more` elements past its length, moving
/// its elements (its length, not its capacity) into a new allocation when
/// it has too little. `Vec::reserve` reallocates, which copies the whole
/// old capacity and doubles it when it is asked for a little more: a
/// G-code run's planner, given room for one block a line and then told
/// there are about two, copied 100,000 reserved blocks holding 528 and,
/// asked for 1.5% more later, doubled 8 MB of them.
pub fn reserve_moving<T>(v: &mut Vec<T>, more: usize) {
    if v.capacity() - v.len() >= more {
        return;
    }
    let mut grown = Vec::with_capacity(v.len() + more);
    grown.append(v);
    *v = grown;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reserve_moving_keeps_the_elements_and_gives_exactly_the_room_asked() {
        let mut v: Vec<u32> = Vec::with_capacity(1000);
        v.extend([7, 8, 9]);
        let before = v.as_ptr();
        reserve_moving(&mut v, 997);
        assert_eq!(
            (v.as_ptr(), v.capacity()),
            (before, 1000),
            "room enough: untouched"
        );
        // A little more than there is room for: Vec::reserve would double
        // the capacity to 2000 (max(2 x 1000, 3 + 1500)); the room asked
        // for is 1503.
        reserve_moving(&mut v, 1500);
        assert_eq!(v, [7, 8, 9]);
        assert!((1503..2000).contains(&v.capacity()), "{}", v.capacity());
        // And a full vector, 10 more: 1013, not 2 x 1503.
        v.resize(v.capacity(), 1);
        let len = v.len();
        reserve_moving(&mut v, 10);
        assert_eq!(&v[..3], [7, 8, 9]);
        assert!(
            (len + 10..2 * len).contains(&v.capacity()),
            "{}",
            v.capacity()
        );
    }
}
