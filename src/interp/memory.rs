//! The memory a program may use (`--max-memory`).
//!
//! A counting global allocator (the `cap` crate) knows how many bytes the
//! process holds. Before the interpreter builds something whose size the
//! program chooses (an array, also a local one, a concatenation, a slice, an
//! aggregate, an allocator) it asks [`room_for`]; past the limit the program gets
//! `Storage_Error` at that place, which it can handle. While a program runs
//! ([`HardCap`]), the allocator itself refuses a quarter past the limit, so
//! memory the interpreter does not ask about cannot take the whole machine;
//! the checker is not capped (its memory grows with the source text).

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

#[global_allocator]
static ALLOC: cap::Cap<std::alloc::System> = cap::Cap::new(std::alloc::System, usize::MAX);

/// The default limit: 4 GiB.
pub const DEFAULT_LIMIT: usize = 4 << 30;

static LIMIT: AtomicUsize = AtomicUsize::new(DEFAULT_LIMIT);
/// Whether runs are capped: set by [`set_limit`] (the command line), not in
/// library use such as the tests.
static CAPPED: AtomicBool = AtomicBool::new(false);

/// Sets the limit for the program's memory and caps runs a quarter above it
/// (plus 256 MiB for adair itself).
pub fn set_limit(bytes: usize) {
    LIMIT.store(bytes, Ordering::Relaxed);
    CAPPED.store(true, Ordering::Relaxed);
}

/// The allocator's hard limit while a program runs; lifted when dropped.
pub struct HardCap(bool);

impl HardCap {
    pub fn arm() -> HardCap {
        if !CAPPED.load(Ordering::Relaxed) {
            return HardCap(false);
        }
        let l = limit();
        let hard = l.saturating_add(l / 4).saturating_add(256 << 20);
        HardCap(ALLOC.set_limit(hard.max(ALLOC.allocated())).is_ok())
    }
}

impl Drop for HardCap {
    fn drop(&mut self) {
        if self.0 {
            let _ = ALLOC.set_limit(usize::MAX);
        }
    }
}

/// The limit in bytes.
pub fn limit() -> usize {
    LIMIT.load(Ordering::Relaxed)
}

/// Bytes the process holds now.
pub fn in_use() -> usize {
    ALLOC.allocated()
}

/// Whether `bytes` more stay within the limit.
pub fn room_for(bytes: usize) -> bool {
    in_use().saturating_add(bytes) <= limit()
}

/// Parses a size as `--max-memory` takes it: a number of bytes, or with a
/// suffix `K`, `M`, `G` (powers of 1024; `KiB`, `MB`, ... are accepted too).
pub fn parse_size(text: &str) -> Result<usize, String> {
    let t = text.trim();
    let split = t.find(|c: char| !c.is_ascii_digit()).unwrap_or(t.len());
    let (num, unit) = t.split_at(split);
    let n: usize = num
        .parse()
        .map_err(|_| format!("`{text}` is not a size (write 512M, 2G or a number of bytes)"))?;
    let shift = match unit.trim().to_ascii_uppercase().as_str() {
        "" | "B" => 0,
        "K" | "KB" | "KIB" => 10,
        "M" | "MB" | "MIB" => 20,
        "G" | "GB" | "GIB" => 30,
        _ => return Err(format!("`{text}`: unknown unit (use K, M or G)")),
    };
    let bytes = n
        .checked_mul(1usize << shift)
        .ok_or_else(|| format!("`{text}` is too large"))?;
    if bytes < 16 << 20 {
        return Err(format!("`{text}` is below 16M, too little to run adair"));
    }
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    use super::parse_size;

    #[test]
    fn sizes() {
        assert_eq!(parse_size("512M"), Ok(512 << 20));
        assert_eq!(parse_size("2G"), Ok(2 << 30));
        assert_eq!(parse_size("2 GiB"), Ok(2 << 30));
        assert_eq!(parse_size("16777216"), Ok(16 << 20));
        assert!(parse_size("1M").unwrap_err().contains("below 16M"));
        assert!(parse_size("lots").unwrap_err().contains("not a size"));
        assert!(parse_size("3T").unwrap_err().contains("unknown unit"));
        assert!(
            parse_size("99999999999999999G")
                .unwrap_err()
                .contains("too large")
        );
    }
}
