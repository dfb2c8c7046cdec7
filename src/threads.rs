//! Independent work items spread over scoped threads: the one parallel loop of the crate
//! (the samples of `curve`, the rows of a margin map, the limit-state searches of `modes`).
//! Items are handed out one at a time (a slow item does not hold up a chunk) and results
//! come back in the items' order, so an answer never depends on the thread count.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

/// `f(i, &items[i])` for every item, on `threads` threads (0 is taken as 1; never more
/// threads than items), in the items' order.
pub fn map<T: Sync, R: Send>(
    items: &[T],
    threads: usize,
    f: impl Fn(usize, &T) -> R + Sync,
) -> Vec<R> {
    let threads = threads.clamp(1, items.len().max(1));
    if threads == 1 {
        return items.iter().enumerate().map(|(i, t)| f(i, t)).collect();
    }
    let next = AtomicUsize::new(0);
    let slots: Vec<Mutex<Option<R>>> = items.iter().map(|_| Mutex::new(None)).collect();
    std::thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                let Some(item) = items.get(i) else { break };
                let r = f(i, item);
                *slots[i].lock().unwrap_or_else(|e| e.into_inner()) = Some(r);
            });
        }
    });
    slots
        .into_iter()
        .map(|s| {
            s.into_inner()
                .unwrap_or_else(|e| e.into_inner())
                .expect("every item is mapped")
        })
        .collect()
}

/// [`map`], with `progress(done, total)` called after each item (from the thread that
/// finished it; `done` counts the items finished so far).
pub fn map_with_progress<T: Sync, R: Send>(
    items: &[T],
    threads: usize,
    progress: &(dyn Fn(usize, usize) + Sync),
    f: impl Fn(usize, &T) -> R + Sync,
) -> Vec<R> {
    let done = AtomicUsize::new(0);
    map(items, threads, |i, t| {
        let r = f(i, t);
        progress(done.fetch_add(1, Ordering::Relaxed) + 1, items.len());
        r
    })
}

/// The number of threads the machine offers (at least 1): the default thread count of the
/// commands that sample independent points.
pub fn available() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}
