//! What the main job prints: lines that never take the run down.

/// `println!` that drops its line if stdout is gone (a closed pipe), rather
/// than panicking mid-run.
macro_rules! say {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stdout(), $($arg)*);
    }};
}
pub(crate) use say;
