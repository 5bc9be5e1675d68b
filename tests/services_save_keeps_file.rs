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
    std::fs::create_dir(target.with_extension("adair-tmp")).unwrap();
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
