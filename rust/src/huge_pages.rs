//! Large buffers the core is about to fill (a trace's steps, the points
//! read from it) asked of the kernel in huge pages, where it has them.
//!
//! Fresh memory comes from the kernel a page at a time, on first touch: a
//! fault per 4 KiB page. Filling 24 MB of points (a 2,000,000-point 3D
//! line) takes about 6,000 faults, and on the bench's machine they cost
//! more than computing the points (`perf`: two thirds of the native
//! end-to-end run in the kernel's fault path). Linux's transparent huge
//! pages serve a range advised with `MADV_HUGEPAGE` in 2 MiB pages, 512
//! times fewer faults, when they are enabled for advised ranges (the
//! default, `madvise` in /sys/kernel/mm/transparent_hugepage/enabled).
//! Only the whole 2 MiB pages inside a buffer are advised, so no page is
//! shared with memory the buffer does not own; the advice changes how the
//! memory is backed, never what it holds. Elsewhere (wasm, other systems)
//! this does nothing: wasm memory, once grown, is the instance's for good.

/// Size of a huge page on the systems that have them (x86-64, aarch64 with 4 KiB pages).
#[cfg(target_os = "linux")]
const HUGE_PAGE_BYTES: usize = 2 << 20;

/// Buffers smaller than this are left alone: two huge pages at least,
/// or the call costs more than the faults it saves.
#[cfg(target_os = "linux")]
const SMALLEST_ADVISED_BYTES: usize = 2 * HUGE_PAGE_BYTES;

/// Advises the whole huge pages inside `memory`, not yet touched, to be
/// backed by huge pages. A refusal (no huge pages configured) is ignored:
/// the memory is then served as before.
#[cfg(target_os = "linux")]
pub fn advise<T>(memory: &mut [T]) {
    let bytes = std::mem::size_of_val(memory);
    if bytes < SMALLEST_ADVISED_BYTES {
        return;
    }
    let start = memory.as_mut_ptr() as usize;
    let first = start.next_multiple_of(HUGE_PAGE_BYTES);
    let end = (start + bytes) / HUGE_PAGE_BYTES * HUGE_PAGE_BYTES;
    if end > first {
        // SAFETY: the range lies inside `memory`, which this call borrows
        // mutably; MADV_HUGEPAGE changes how the pages are backed, never
        // their contents.
        unsafe {
            libc::madvise(first as *mut libc::c_void, end - first, libc::MADV_HUGEPAGE);
        }
    }
}

/// Does nothing where there are no transparent huge pages to ask for.
#[cfg(not(target_os = "linux"))]
pub fn advise<T>(_memory: &mut [T]) {}
