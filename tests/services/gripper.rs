//! The gripper readings agree everywhere: the `--trace` line of a `MoveTool`
//! and `ValueTool` report the same opening and grip force (the TeachBox reads
//! the same `services::grip_reading`; tests/terminal.rs checks its screen).
//! The grip force is a setting: `InitToolForce` after `InitRobot`, then the
//! `Force` of the last `MoveTool`.

fn trace_force(line: &str) -> (f64, f64) {
    // "... opening 60.0 -> 25.0 mm, force 5.0 N"
    let to = line.split("-> ").nth(1).unwrap().split(' ').next().unwrap();
    let f = line
        .split("force ")
        .nth(1)
        .unwrap()
        .split(' ')
        .next()
        .unwrap();
    (to.parse().unwrap(), f.parse().unwrap())
}

#[test]
fn trace_and_value_tool_agree() {
    let src = "procedure Show is\n   T : constant ToolDescriptor := ValueTool;\nbegin\n   \
               Put_Line (\"value\" & Float'Image (T.CurrDist) & Float'Image (T.CurrForce));\nend Show;\n\
               InitRobot;\nShow;\n\
               MoveTool (25.0, 5.0);\nShow;\n\
               MoveTool (60.0, 20.0);\nShow;\n\
               PlaceObject (30.0);\n\
               MoveTool (10.0, 12.0);\nShow;\n\
               MoveTool (0.0, 7.0);\nShow;\n";
    let r = adair::golden::run_text("grip.air", src, "rv-m1", true);
    assert_eq!(r.code, 0, "{}{}", r.output, r.diagnostics);
    let lines: Vec<&str> = r.output.lines().collect();
    // After InitRobot: open 60 mm, force InitToolForce = 10 N.
    let first = lines.iter().find(|l| l.starts_with("value")).unwrap();
    assert_eq!(*first, "value 6.00000E+01 1.00000E+01", "{}", r.output);
    let mut pairs = 0;
    for (k, l) in lines.iter().enumerate() {
        if l.contains("MoveTool at") {
            let (opening, force) = trace_force(l);
            let v: Vec<f64> = lines[k + 1]
                .trim_start_matches("value")
                .split_whitespace()
                .map(|x| x.parse().unwrap())
                .collect();
            assert_eq!((opening, force), (v[0], v[1]), "{l} / {}", lines[k + 1]);
            pairs += 1;
        }
    }
    assert_eq!(pairs, 4, "{}", r.output);
    // The forces the program asked for are what every reader reports.
    assert!(
        r.output.contains("opening 60.0 -> 25.0 mm, force 5.0 N"),
        "{}",
        r.output
    );
    assert!(
        r.output.contains("opening 60.0 -> 30.0 mm, force 12.0 N"),
        "{}",
        r.output
    );
}

#[test]
fn pressing_reads_the_force_the_jaws_press_with_not_the_setting() {
    // A tool whose force range goes past what the RV-M1's jaws can do
    // (30 N): asked for 80 N, they press on the part with 30 N, and that is
    // what ValueTool reads while they press; once open again, the setting.
    // A force exactly at the range's end is allowed.
    let src = "procedure Show is\n   T : constant ToolDescriptor := ValueTool;\nbegin\n   \
               Put_Line (\"value\" & Float'Image (T.CurrDist) & Float'Image (T.CurrForce));\nend Show;\n\
               T : ToolDescriptor;\n\
               InitRobot;\nT := ValueTool;\nT.ForceMax := 80.0;\nSetTool (T);\n\
               PlaceObject (30.0);\n\
               MoveTool (10.0, 80.0);\nShow;\n\
               MoveTool (60.0, 25.0);\nShow;\n";
    let r = adair::golden::run_text("press.air", src, "rv-m1", false);
    assert_eq!(r.code, 0, "{}{}", r.output, r.diagnostics);
    let values: Vec<&str> = r
        .output
        .lines()
        .filter(|l| l.starts_with("value"))
        .collect();
    assert_eq!(
        values,
        [
            "value 3.00000E+01 3.00000E+01",
            "value 6.00000E+01 2.50000E+01"
        ],
        "{}",
        r.output
    );
}
