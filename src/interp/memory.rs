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

/// The process's allocator. The tests build `cap` with its `stats` feature
/// (a dev-dependency), so that they can count the bytes a piece of work
/// allocates (`tests/repl_linear.rs`); adair's own build does not pay for it.
#[global_allocator]
pub static ALLOC: cap::Cap<std::alloc::System> = cap::Cap::new(std::alloc::System, usize::MAX);

/// The most the default limit is: 4 GiB (also the limit of library use,
/// such as the tests).
pub const DEFAULT_LIMIT: usize = 4 << 30;

/// The default `--max-memory`: what the process can really have, less
/// adair's own share, and at most [`DEFAULT_LIMIT`]. The real limits are the
/// address-space limit (`ulimit -v`, `RLIMIT_AS`), the cgroup's
/// `memory.max` (a container's) and the physical memory; past any of them
/// an allocation fails or the process is killed, where the program should
/// have had `Storage_Error`.
pub fn default_limit() -> usize {
    derive_limit(address_space(), cgroup_max(), physical())
}

/// The default limit from the real ones, in bytes (`None`: no such
/// limit). The address space also holds the run's 512 MiB stack, the code
/// and the allocator's arenas (1 GiB in all is kept for them); and the
/// allocator's hard cap while a program runs is the limit plus a quarter
/// plus 256 MiB ([`HardCap`]), which must stay within the real limit.
pub fn derive_limit(
    address_space: Option<u64>,
    cgroup: Option<u64>,
    physical: Option<u64>,
) -> usize {
    let from_as = address_space.map(|a| a.saturating_sub(1 << 30));
    let Some(real) = [from_as, cgroup, physical].into_iter().flatten().min() else {
        return DEFAULT_LIMIT;
    };
    let fit = real.saturating_sub(256 << 20) / 5 * 4;
    usize::try_from(fit)
        .unwrap_or(usize::MAX)
        .clamp(16 << 20, DEFAULT_LIMIT)
}

/// The soft `RLIMIT_AS`, when there is one.
fn address_space() -> Option<u64> {
    use nix::sys::resource::{RLIM_INFINITY, Resource, getrlimit};
    let (soft, _) = getrlimit(Resource::RLIMIT_AS).ok()?;
    (soft != RLIM_INFINITY).then_some(soft)
}

/// A cgroup memory limit as its file holds it: bytes, or `max` (none).
pub fn parse_cgroup_limit(text: &str) -> Option<u64> {
    let t = text.trim();
    // cgroup v1 writes "no limit" as a page-rounded i64::MAX.
    t.parse::<u64>().ok().filter(|n| *n < 1 << 62)
}

/// The lowest `memory.max` of this process's cgroup and those above it
/// (cgroup v2, from `/proc/self/cgroup`), or cgroup v1's
/// `memory.limit_in_bytes`.
fn cgroup_max() -> Option<u64> {
    let root = std::path::Path::new("/sys/fs/cgroup");
    let own = read_small("/proc/self/cgroup")
        .and_then(|t| {
            t.lines().find_map(|l| {
                l.strip_prefix("0::")
                    .map(|p| p.trim_start_matches('/').to_string())
            })
        })
        .unwrap_or_default();
    let mut dir = root.join(own);
    let mut lowest: Option<u64> = None;
    loop {
        if let Some(n) = read_small(dir.join("memory.max")).and_then(|t| parse_cgroup_limit(&t)) {
            lowest = Some(lowest.map_or(n, |l| l.min(n)));
        }
        if dir == root || !dir.pop() {
            break;
        }
    }
    let v1 =
        read_small(root.join("memory/memory.limit_in_bytes")).and_then(|t| parse_cgroup_limit(&t));
    [lowest, v1].into_iter().flatten().min()
}

/// A small file of `/proc` or `/sys`, read in one go: `read_to_string`
/// asks for its size (which such files do not say) and then reads it 32
/// bytes at a time, a system call each (start-up, issue 32 item 4).
fn read_small(path: impl AsRef<std::path::Path>) -> Option<String> {
    use std::io::Read;
    let mut text = String::with_capacity(4096);
    std::fs::File::open(path)
        .ok()?
        .take(1 << 20)
        .read_to_string(&mut text)
        .ok()?;
    Some(text)
}

/// The machine's memory (`MemTotal` of `/proc/meminfo`, its first line:
/// the file's first block is read, not the whole).
fn physical() -> Option<u64> {
    use std::io::Read;
    let mut head = [0u8; 512];
    let n = std::fs::File::open("/proc/meminfo")
        .ok()?
        .read(&mut head)
        .ok()?;
    let text = std::str::from_utf8(head.get(..n)?).ok()?;
    let kib: u64 = text
        .lines()
        .find_map(|l| l.strip_prefix("MemTotal:"))?
        .trim()
        .trim_end_matches("kB")
        .trim()
        .parse()
        .ok()?;
    kib.checked_mul(1024)
}

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
    use super::{DEFAULT_LIMIT, derive_limit, parse_cgroup_limit, parse_size};

    #[test]
    fn the_default_limit_is_the_smallest_real_one_less_adairs_share() {
        const G: u64 = 1 << 30;
        // No limit anywhere: 4G.
        assert_eq!(derive_limit(None, None, None), DEFAULT_LIMIT);
        // A big machine: still 4G.
        assert_eq!(derive_limit(None, None, Some(64 * G)), DEFAULT_LIMIT);
        // 2 GiB of RAM: (2G - 256M) * 4/5.
        assert_eq!(
            derive_limit(None, None, Some(2 * G)),
            ((2 * G - (256 << 20)) / 5 * 4) as usize
        );
        // The smallest wins, whichever it is.
        let cg = derive_limit(Some(8 * G), Some(G), Some(16 * G));
        assert_eq!(cg, derive_limit(None, Some(G), None));
        assert!(cg < G as usize && cg > (G / 2) as usize, "{cg}");
        // ulimit -v 2G: 1 GiB of it for stacks and code.
        let v = derive_limit(Some(2 * G), None, Some(16 * G));
        assert_eq!(v, ((G - (256 << 20)) / 5 * 4) as usize);
        // The hard cap (limit + a quarter + 256 MiB) fits what is left.
        assert!(v + v / 4 + (256 << 20) <= G as usize);
        // Less than adair needs: the least --max-memory takes.
        assert_eq!(derive_limit(Some(G), None, None), 16 << 20);
    }

    #[test]
    fn cgroup_limits() {
        assert_eq!(parse_cgroup_limit("max\n"), None);
        assert_eq!(parse_cgroup_limit("536870912\n"), Some(512 << 20));
        assert_eq!(parse_cgroup_limit("9223372036854771712\n"), None);
        assert_eq!(parse_cgroup_limit(""), None);
    }

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
