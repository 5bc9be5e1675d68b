//! `SavePathSystem` and `LoadPathSystem` on names that are not plain files
//! of ours (issue 35): a symlink is written through (its target replaced
//! whole, the link kept); a FIFO, a device or a directory is `Use_Error`
//! naming it, and is left as it was; a file without write permission is
//! `Use_Error` (also as root); a load never blocks in `open` (a FIFO or a
//! device is refused). The device cases need root (`mknod`); without it
//! they are skipped with a message.

use std::os::unix::fs::{FileTypeExt, PermissionsExt};
use std::path::{Path, PathBuf};
use std::time::Duration;

fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("adair_file_kinds_{name}_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Runs a script with a path 1 of one position that saves (or loads) `name`
/// and prints `done` or the exception's name and message. Runs in a thread:
/// a load that blocks is a failure after ten seconds (the FIFO is then
/// opened for writing, which lets the blocked `open` go on).
fn try_file(dir: &Path, name: &Path, load: bool) -> String {
    let script = dir.join(if load { "load.air" } else { "save.air" });
    let call = if load {
        "LoadPathSystem"
    } else {
        "SavePathSystem"
    };
    std::fs::write(
        &script,
        format!(
            "InitRobot;\nCreatePath ({});\nInsertPosition ({0}, 1, Trans (300.0, 0.0, 200.0));\n\
             begin\n   {call} (\"{}\");\n   Put_Line (\"done\");\nexception\n   \
             when E : others => Put_Line (Ada.Exceptions.Exception_Name (E) & \": \" & \
             Ada.Exceptions.Exception_Message (E));\nend;\n",
            if load { 9 } else { 1 },
            name.display()
        ),
    )
    .unwrap();
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let _ = tx.send(adair::golden::run_case(&script));
    });
    match rx.recv_timeout(Duration::from_secs(10)) {
        Ok(out) => out,
        Err(_) => {
            // Unblock the reader so that the test process can end.
            let _ = std::fs::OpenOptions::new().write(true).open(name);
            panic!("{call} ({}) blocked", name.display());
        }
    }
}

/// A saved file with one path, to load or to find.
fn saved(dir: &Path) -> Vec<u8> {
    let f = dir.join("ref.paths");
    assert_eq!(try_file(dir, &f, false), "done\n");
    let bytes = std::fs::read(&f).unwrap();
    std::fs::remove_file(&f).unwrap();
    bytes
}

fn left_in(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| !n.ends_with(".air"))
        .collect();
    v.sort();
    v
}

fn use_error_naming(out: &str, name: &Path, what: &str) {
    assert!(
        out.starts_with("ADA.IO_EXCEPTIONS.USE_ERROR: ")
            && out.contains(&name.display().to_string())
            && out.contains(what),
        "expected Use_Error naming {} as {what}: {out}",
        name.display()
    );
}

#[test]
fn a_save_to_a_fifo_is_a_use_error_and_the_fifo_stays() {
    let dir = temp("fifo_save");
    let fifo = dir.join("pipe.paths");
    nix::unistd::mkfifo(&fifo, nix::sys::stat::Mode::from_bits_truncate(0o644)).unwrap();
    let out = try_file(&dir, &fifo, false);
    let kind = std::fs::symlink_metadata(&fifo).unwrap().file_type();
    let left = left_in(&dir);
    let _ = std::fs::remove_dir_all(&dir);
    use_error_naming(&out, &fifo, "FIFO");
    assert!(kind.is_fifo(), "the FIFO was replaced: {kind:?}");
    assert_eq!(left, ["pipe.paths"]);
}

#[test]
fn a_load_from_a_fifo_is_a_use_error_at_once() {
    let dir = temp("fifo_load");
    let fifo = dir.join("pipe.paths");
    nix::unistd::mkfifo(&fifo, nix::sys::stat::Mode::from_bits_truncate(0o644)).unwrap();
    let out = try_file(&dir, &fifo, true);
    let _ = std::fs::remove_dir_all(&dir);
    use_error_naming(&out, &fifo, "FIFO");
}

#[test]
fn a_save_to_a_directory_is_a_use_error() {
    let dir = temp("dir_save");
    let sub = dir.join("cell.paths");
    std::fs::create_dir(&sub).unwrap();
    let out = try_file(&dir, &sub, false);
    let load = try_file(&dir, &sub, true);
    let still = sub.is_dir() && std::fs::read_dir(&sub).unwrap().count() == 0;
    let _ = std::fs::remove_dir_all(&dir);
    use_error_naming(&out, &sub, "directory");
    use_error_naming(&load, &sub, "directory");
    assert!(still, "the directory was changed");
}

#[test]
fn a_save_through_a_symlink_replaces_its_target_and_keeps_the_link() {
    let dir = temp("link_save");
    let real = dir.join("real.paths");
    std::fs::write(&real, "adair-paths 1\n").unwrap();
    let link = dir.join("link.paths");
    std::os::unix::fs::symlink("real.paths", &link).unwrap();
    let out = try_file(&dir, &link, false);
    let is_link = std::fs::symlink_metadata(&link)
        .unwrap()
        .file_type()
        .is_symlink();
    let target = std::fs::read(&real).unwrap();
    let expected = saved(&dir);
    let left = left_in(&dir);
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(out, "done\n");
    assert!(is_link, "the link was replaced by a file");
    assert_eq!(target, expected, "the link's target keeps the old paths");
    assert_eq!(left, ["link.paths", "real.paths"]);
}

#[test]
fn a_save_through_a_dangling_symlink_creates_its_target() {
    let dir = temp("link_dangling");
    let sub = dir.join("sub");
    std::fs::create_dir(&sub).unwrap();
    let link = dir.join("link.paths");
    std::os::unix::fs::symlink("sub/new.paths", &link).unwrap();
    let out = try_file(&dir, &link, false);
    let target = std::fs::read(sub.join("new.paths"));
    let is_link = std::fs::symlink_metadata(&link)
        .unwrap()
        .file_type()
        .is_symlink();
    let expected = saved(&dir);
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(out, "done\n");
    assert!(is_link, "the link was replaced by a file");
    assert_eq!(target.unwrap(), expected);
}

#[test]
fn a_read_only_file_is_a_use_error_even_as_root() {
    let dir = temp("read_only");
    let f = dir.join("cell.paths");
    std::fs::write(&f, "adair-paths 1\n").unwrap();
    std::fs::set_permissions(&f, std::fs::Permissions::from_mode(0o444)).unwrap();
    let out = try_file(&dir, &f, false);
    let after = std::fs::read_to_string(&f).unwrap();
    let left = left_in(&dir);
    let _ = std::fs::remove_dir_all(&dir);
    use_error_naming(&out, &f, "not writable");
    assert_eq!(after, "adair-paths 1\n");
    assert_eq!(left, ["cell.paths"]);
}

/// A save keeps the permissions of the file it replaces.
#[test]
fn a_save_keeps_the_permissions_of_the_file() {
    let dir = temp("mode");
    let f = dir.join("cell.paths");
    std::fs::write(&f, "adair-paths 1\n").unwrap();
    std::fs::set_permissions(&f, std::fs::Permissions::from_mode(0o600)).unwrap();
    let out = try_file(&dir, &f, false);
    let mode = std::fs::metadata(&f).unwrap().permissions().mode() & 0o777;
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(out, "done\n");
    assert_eq!(mode, 0o600);
}

fn is_root() -> bool {
    nix::unistd::geteuid().is_root()
}

#[test]
#[allow(clippy::print_stdout)] // says when it is skipped
fn a_device_is_a_use_error_and_stays_a_device() {
    if !is_root() {
        println!("skipped: making a device file (mknod) needs root");
        return;
    }
    let dir = temp("device");
    let dev = dir.join("null");
    nix::sys::stat::mknod(
        &dev,
        nix::sys::stat::SFlag::S_IFCHR,
        nix::sys::stat::Mode::from_bits_truncate(0o666),
        nix::sys::stat::makedev(1, 3),
    )
    .unwrap();
    let out = try_file(&dir, &dev, false);
    let load = try_file(&dir, &dev, true);
    // Through a link, too.
    let link = dir.join("link.paths");
    std::os::unix::fs::symlink(&dev, &link).unwrap();
    let via_link = try_file(&dir, &link, false);
    let kind = std::fs::symlink_metadata(&dev).unwrap().file_type();
    let left = left_in(&dir);
    let _ = std::fs::remove_dir_all(&dir);
    use_error_naming(&out, &dev, "device");
    use_error_naming(&load, &dev, "device");
    use_error_naming(&via_link, &dev, "device");
    assert!(kind.is_char_device(), "the device was replaced: {kind:?}");
    assert_eq!(left, ["link.paths", "null"]);
}

/// As root, saving over another user's file leaves it theirs (the new file
/// gets the old one's owner and group), with its permissions.
#[test]
#[allow(clippy::print_stdout)] // says when it is skipped
fn a_save_as_root_keeps_the_owner_of_the_file() {
    use std::os::unix::fs::MetadataExt;
    if !is_root() {
        println!("skipped: giving a file to another user (chown) needs root");
        return;
    }
    let dir = temp("owner");
    let f = dir.join("cell.paths");
    std::fs::write(&f, "adair-paths 1\n").unwrap();
    std::fs::set_permissions(&f, std::fs::Permissions::from_mode(0o664)).unwrap();
    std::os::unix::fs::chown(&f, Some(65534), Some(65534)).unwrap();
    let out = try_file(&dir, &f, false);
    let m = std::fs::metadata(&f).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(out, "done\n");
    assert_eq!((m.uid(), m.gid(), m.mode() & 0o777), (65534, 65534, 0o664));
}
