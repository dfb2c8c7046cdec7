//! A hello-world process: the baseline of `perf_table`'s one-shot process CPU time.

fn main() {
    println!("hello");
}
