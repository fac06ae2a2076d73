//! A few results derived from a slices file, kept for the next case of the same scene: the grid
//! search's rail heights on its gap mesh (one cross-section per mesh column, CONTACT's
//! `varprof_intpol_grid_old`) are the same for every case whose wheelset stands at the same S_WS
//! over the same mesh, and cost more than the rest of the case's search.

use std::sync::{Arc, Mutex};

/// How many results are kept (the oldest goes first): a scene's cases at a few positions.
const KEPT: usize = 4;

/// A result and the bits of what it was made from.
type Entry = (Vec<u64>, Arc<Vec<f64>>);

/// Results keyed by the bits of what they were made from; a clone starts empty.
#[derive(Debug, Default)]
pub struct Memo {
    kept: Mutex<Vec<Entry>>,
}

impl Clone for Memo {
    fn clone(&self) -> Self {
        Memo::default()
    }
}

impl Memo {
    /// The result kept for `key`, or `make()`'s, then kept. `make` runs outside the lock, so two
    /// threads may both make a missing result: `make` must be a function of `key` alone, and
    /// either copy is then the same bit for bit.
    pub fn get_or_make(&self, key: &[u64], make: impl FnOnce() -> Vec<f64>) -> Arc<Vec<f64>> {
        if let Some(hit) = self.lock().iter().find(|(k, _)| k == key) {
            return Arc::clone(&hit.1);
        }
        let made = Arc::new(make());
        let mut kept = self.lock();
        if !kept.iter().any(|(k, _)| k == key) {
            if kept.len() == KEPT {
                kept.remove(0);
            }
            kept.push((key.to_vec(), Arc::clone(&made)));
        }
        made
    }

    /// The kept results; a lock poisoned by a panic elsewhere still holds whole results.
    fn lock(&self) -> std::sync::MutexGuard<'_, Vec<Entry>> {
        self.kept.lock().unwrap_or_else(|e| e.into_inner())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_kept_result_is_returned_and_the_oldest_goes_first() {
        let memo = Memo::default();
        let mut made = 0;
        for key in [1u64, 2, 1, 3, 4, 5, 1] {
            memo.get_or_make(&[key], || {
                made += 1;
                vec![key as f64]
            });
        }
        // 1, 2 made; 1 kept; 3, 4 made (four kept); 5 made, 1 dropped; 1 made again.
        assert_eq!(made, 6);
        assert_eq!(*memo.get_or_make(&[5], || vec![0.0]), vec![5.0]);
        assert_eq!(memo.clone().lock().len(), 0);
    }
}
