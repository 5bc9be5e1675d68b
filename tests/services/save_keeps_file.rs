//! SavePathSystem replaces an existing file only by a complete new one: a
//! save that fails leaves the previous file byte for byte as it was, and it
//! still loads. (The golden scripts cannot make a save to an existing file
//! fail; here the temporary file's place is taken by a directory.)

use std::path::Path;

fn run(dir: &Path, name: &str, body: &str) -> String {
    let script = dir.join(name);
    std::fs::write(&script, body).unwrap();
    adair::golden::run_case(&script)
}

#[test]
fn failed_save_leaves_the_previous_file_whole() {
    let dir = std::env::temp_dir().join(format!("adair_save_keep_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let target = dir.join("cell.paths");
    let first = run(
        &dir,
        "first.air",
        &format!(
            "InitRobot;\nCreatePath (1);\nInsertPosition (1, 1, Trans (300.0, 0.0, 200.0));\n\
             SavePathSystem (\"{}\");\nPut_Line (\"saved\");\n",
            target.display()
        ),
    );
    assert_eq!(first, "saved\n");
    let before = std::fs::read(&target).unwrap();
    // The new file is written next to the target first: make that fail.
    std::fs::create_dir(dir.join("cell.paths.adair-tmp")).unwrap();
    let second = run(
        &dir,
        "second.air",
        &format!(
            "F : Frame;\nInitRobot;\nCreatePath (1);\n\
             InsertPosition (1, 1, Trans (100.0, 50.0, 300.0));\n\
             InsertPosition (1, 2, Trans (200.0, 50.0, 300.0));\n\
             begin\n   SavePathSystem (\"{0}\");\n   Put_Line (\"saved (wrong)\");\n\
             exception\n   when E : Ada.IO_Exceptions.Use_Error => Put_Line (Ada.Exceptions.Exception_Name (E));\nend;\n\
             DeletePath (1);\nLoadPathSystem (\"{0}\");\nValuePosition (1, 1, F);\n\
             Put_Line (\"old file loads: \" & Boolean'Image (F = Trans (300.0, 0.0, 200.0)));\n",
            target.display()
        ),
    );
    let after = std::fs::read(&target).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(
        second,
        "ADA.IO_EXCEPTIONS.USE_ERROR\nold file loads: TRUE\n"
    );
    assert_eq!(after, before, "the previous file was changed");
}

/// A path file that is not UTF-8 text is malformed content: `Data_Error`
/// naming the line, not `Use_Error`; nothing is loaded.
#[test]
fn a_path_file_that_is_not_utf8_is_a_data_error() {
    let dir = std::env::temp_dir().join(format!("adair_utf8_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let target = dir.join("bad.paths");
    std::fs::write(&target, b"adair-paths 1\npath 1\npos 1 \xff\xfe 0.0\nend\n").unwrap();
    let out = run(
        &dir,
        "load.air",
        &format!(
            "InitRobot;\nbegin\n   LoadPathSystem (\"{}\");\n   Put_Line (\"loaded (wrong)\");\n\
             exception\n   when E : others => Put_Line (Ada.Exceptions.Exception_Name (E) & \": \" & Ada.Exceptions.Exception_Message (E));\nend;\n\
             begin\n   DeletePath (1);\n   Put_Line (\"path 1 exists (wrong)\");\n\
             exception\n   when PathNotDefined => Put_Line (\"nothing loaded\");\nend;\n",
            target.display()
        ),
    );
    let _ = std::fs::remove_dir_all(&dir);
    assert!(
        out.starts_with("ADA.IO_EXCEPTIONS.DATA_ERROR: ") && out.contains("bad.paths:3: not UTF-8"),
        "{out}"
    );
    assert!(out.ends_with("nothing loaded\n"), "{out}");
}

/// A save killed half-way leaves `NAME.adair-tmp`; the next save of that
/// file writes over it and renames it, so nothing is left behind. Saves of
/// two files that differ only in their extension do not share a temporary.
#[test]
fn a_stale_temporary_from_a_killed_save_is_gone_after_the_next_save() {
    let dir = std::env::temp_dir().join(format!("adair_save_stale_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let target = dir.join("cell.paths");
    let stale = dir.join("cell.paths.adair-tmp");
    std::fs::write(&stale, "AdaIR paths 1\npath 1\n  half a li").unwrap();
    // The other file's temporary would have been `cell.adair-tmp` too.
    let other = dir.join("cell.txt");
    let out = run(
        &dir,
        "save.air",
        &format!(
            "InitRobot;\nCreatePath (1);\nInsertPosition (1, 1, Trans (300.0, 0.0, 200.0));\n\
             SavePathSystem (\"{}\");\nSavePathSystem (\"{}\");\n\
             DeletePath (1);\nLoadPathSystem (\"{}\");\nPut_Line (\"loaded\");\n",
            target.display(),
            other.display(),
            target.display()
        ),
    );
    let mut left: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    left.sort();
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(out, "loaded\n");
    assert_eq!(left, ["cell.paths", "cell.txt", "save.air"]);
}

/// A path file name that names no file, or a directory that does not exist,
/// is `Name_Error` before anything is written; a missing file to load is
/// `Name_Error` too (not `Use_Error`).
#[test]
fn file_names_refused_before_writing() {
    let dir = std::env::temp_dir().join(format!("adair_path_names_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let missing_dir = dir.join("no_such_dir").join("cell.paths");
    let missing_file = dir.join("no_such_file.paths");
    let mut script = String::from(
        "procedure Try (Name : String; Load : Boolean) is\nbegin\n   \
         if Load then LoadPathSystem (Name); else SavePathSystem (Name); end if;\n   \
         Put_Line (\"done\");\nexception\n   \
         when E : others => Put_Line (Ada.Exceptions.Exception_Name (E));\nend Try;\n\
         InitRobot;\nCreatePath (1);\nInsertPosition (1, 1, Trans (300.0, 0.0, 200.0));\n",
    );
    for (name, load) in [
        ("/".to_string(), false),
        ("".to_string(), false),
        (missing_dir.display().to_string(), false),
        (missing_file.display().to_string(), true),
    ] {
        script.push_str(&format!(
            "Try (\"{name}\", {});\n",
            if load { "True" } else { "False" }
        ));
    }
    let out = run(&dir, "names.air", &script);
    assert_eq!(out, "ADA.IO_EXCEPTIONS.NAME_ERROR\n".repeat(4), "{script}");
    assert!(!missing_dir.parent().unwrap().exists());
    let _ = std::fs::remove_dir_all(&dir);
}
