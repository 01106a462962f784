//! Consecutive stretches of an index space, kept as where each starts:
//! stretch i runs from its start up to the next one's, the last up to the
//! end. A trace's segments over its steps, and a program's moves over its
//! steps and its planner blocks, are kept so: 8 or 4 bytes a stretch, and
//! no length that the next start already says.

/// The starts of consecutive stretches (nondecreasing), and where the last
/// one ends.
#[derive(Clone, Debug, Default)]
pub struct Starts<T> {
    first: Vec<T>,
    end: T,
}

impl<T: Copy + Ord> Starts<T> {
    /// Adds a stretch starting at `start`, where the one before it ends.
    pub fn push(&mut self, start: T) {
        self.first.push(start);
    }

    /// Makes room for `more` stretches.
    pub fn reserve(&mut self, more: usize) {
        self.first.reserve(more);
    }

    /// Ends the last stretch at `end`, and gives back the memory the starts
    /// grew past their length.
    pub fn finish(&mut self, end: T) {
        self.end = end;
        self.first.shrink_to_fit();
    }

    pub fn len(&self) -> usize {
        self.first.len()
    }

    pub fn is_empty(&self) -> bool {
        self.first.is_empty()
    }

    /// Where the last stretch ends.
    pub fn end(&self) -> T {
        self.end
    }

    /// Stretch `i`: where it starts and where it ends (the next one's
    /// start, or the end).
    pub fn span(&self, i: usize) -> (T, T) {
        let end = self.first.get(i + 1).copied().unwrap_or(self.end);
        (self.first[i], end)
    }

    /// The stretch holding index `k` (below the end): the last one that
    /// starts at or before it, as those before it that start there too are
    /// empty. 0 when there is none.
    pub fn holding(&self, k: T) -> usize {
        self.first.partition_point(|&f| f <= k).saturating_sub(1)
    }

    /// The first stretch that starts at or after index `k`.
    pub fn first_from(&self, k: T) -> usize {
        self.first.partition_point(|&f| f < k)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn empty_stretches_hold_no_index() {
        // Stretches 0..3, 3..3 (empty), 3..7, 7..7 (empty, the last).
        let mut s = Starts::default();
        for start in [0u64, 3, 3, 7] {
            s.push(start);
        }
        s.finish(7);
        assert_eq!(
            (0..4).map(|i| s.span(i)).collect::<Vec<_>>(),
            [(0, 3), (3, 3), (3, 7), (7, 7)]
        );
        assert_eq!(
            (0..7).map(|k| s.holding(k)).collect::<Vec<_>>(),
            [0, 0, 0, 2, 2, 2, 2]
        );
        assert_eq!(
            (0..=8).map(|k| s.first_from(k)).collect::<Vec<_>>(),
            [0, 1, 1, 1, 3, 3, 3, 3, 4]
        );
    }
}
