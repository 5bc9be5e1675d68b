//! The report of `adair test`: a progress line per script, the diff of
//! expected and actual output with context and a legend, and JUnit XML.

use super::*;

/// ANSI colours of a report on a terminal.
struct Paint(bool);

impl Paint {
    fn wrap(&self, code: &str, text: &str) -> String {
        if self.0 {
            format!("\x1b[{code}m{text}\x1b[0m")
        } else {
            text.to_string()
        }
    }
}

/// The line (and, for a failure, the explanation) `adair test` prints for
/// one script; `paint` colours it for a terminal.
pub fn progress(r: &CaseResult, paint: bool) -> String {
    let p = Paint(paint);
    let shown = r.script.display();
    let time = if r.seconds >= 0.5 {
        format!(" ({:.1} s)", r.seconds)
    } else {
        String::new()
    };
    let exp = expected_path(&r.script);
    let exp_name = shown_name(&exp);
    match &r.verdict {
        Verdict::Pass => format!("{} {shown}{time}\n", p.wrap("32", "ok  ")),
        Verdict::Blessed => format!("{} {shown}{time}\n", p.wrap("33", "blessed")),
        Verdict::Missing { actual } => format!(
            "{} {shown}: no {} (run with --bless to create it); it printed{}",
            p.wrap("1;31", "FAIL"),
            exp.display(),
            if actual.is_empty() {
                " nothing\n".to_string()
            } else {
                format!(":\n{}", indent(actual))
            }
        ),
        Verdict::Differs { expected, actual } => format!(
            "{} {shown}{time}: the output differs from {exp_name}\n{}",
            p.wrap("1;31", "FAIL"),
            diff_with(
                expected,
                actual,
                &exp_name,
                &format!("{}'s output", shown_name(&r.script)),
                paint
            )
        ),
        Verdict::Config(e) => format!(
            "{} {shown}: a configuration error (nothing ran; --bless does not write it):\n{}\n",
            p.wrap("1;31", "FAIL"),
            indent(e).trim_end()
        ),
        Verdict::TimedOut { limit, partial } => format!(
            "{} {shown}: still running after {} s (wall clock), stopped (as Ctrl-C stops a \
             run); a longer limit: --timeout SECONDS, or a first line \
             `-- adair: --timeout SECONDS`{}",
            p.wrap("1;31", "FAIL"),
            limit,
            match partial {
                Some(t) if !t.is_empty() => format!("; it printed:\n{}", indent(t)),
                _ => "\n".into(),
            }
        ),
        Verdict::Crashed(e) => format!("{} {shown}: {}\n", p.wrap("1;31", "FAIL"), e.trim_end()),
    }
}

/// `text` with each line indented by four spaces.
fn indent(text: &str) -> String {
    text.lines().map(|l| format!("    {l}\n")).collect()
}

/// Lines of context around each change in a diff.
const CONTEXT: usize = 3;

/// One line of a diff: in both texts (expected and actual line indices),
/// only in the expected text, or only in the actual one.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Edit {
    Same(usize, usize),
    Gone(usize),
    New(usize),
}

/// The edits from `e` to `a`: a longest common subsequence of lines (the
/// changed middle only, after the common start and end; past about four
/// million line pairs, the middle is shown as removed and added whole).
fn edits(e: &[&str], a: &[&str]) -> Vec<Edit> {
    let pre = e.iter().zip(a).take_while(|(x, y)| x == y).count();
    let suf = e[pre..]
        .iter()
        .rev()
        .zip(a[pre..].iter().rev())
        .take_while(|(x, y)| x == y)
        .count();
    let (em, am) = (&e[pre..e.len() - suf], &a[pre..a.len() - suf]);
    let mut out: Vec<Edit> = (0..pre).map(|i| Edit::Same(i, i)).collect();
    let (n, m) = (em.len(), am.len());
    if n.saturating_mul(m) <= 4_000_000 {
        // lcs[i][j]: the longest common subsequence of em[i..] and am[j..].
        let w = m + 1;
        let mut lcs = vec![0u32; (n + 1) * w];
        for i in (0..n).rev() {
            for j in (0..m).rev() {
                lcs[i * w + j] = if em[i] == am[j] {
                    lcs[(i + 1) * w + j + 1] + 1
                } else {
                    lcs[(i + 1) * w + j].max(lcs[i * w + j + 1])
                };
            }
        }
        let (mut i, mut j) = (0, 0);
        while i < n || j < m {
            if i < n && j < m && em[i] == am[j] {
                out.push(Edit::Same(pre + i, pre + j));
                i += 1;
                j += 1;
            } else if j == m || (i < n && lcs[(i + 1) * w + j] >= lcs[i * w + j + 1]) {
                out.push(Edit::Gone(pre + i));
                i += 1;
            } else {
                out.push(Edit::New(pre + j));
                j += 1;
            }
        }
    } else {
        out.extend((0..n).map(|i| Edit::Gone(pre + i)));
        out.extend((0..m).map(|j| Edit::New(pre + j)));
    }
    out.extend((0..suf).map(|k| Edit::Same(e.len() - suf + k, a.len() - suf + k)));
    out
}

/// A line diff of expected and actual text, for failure reports, without
/// colour: see [`diff_with`].
pub fn diff(expected: &str, actual: &str) -> String {
    diff_with(expected, actual, "", "", false)
}

/// A line diff with a legend (`-` lines are the expected text, named
/// `expected_name`, `+` lines the actual one) and three lines of context
/// around each change, each line with its number in its own text (names
/// left empty: the legend is `--- expected` and `+++ actual`); coloured
/// for a terminal when `paint` (expected red, actual green).
pub fn diff_with(
    expected: &str,
    actual: &str,
    expected_name: &str,
    actual_name: &str,
    paint: bool,
) -> String {
    let p = Paint(paint);
    let (e, a): (Vec<&str>, Vec<&str>) = (expected.lines().collect(), actual.lines().collect());
    let named = |side: &str, name: &str| {
        if name.is_empty() {
            side.to_string()
        } else {
            format!("{side}: {name}")
        }
    };
    let mut out = format!(
        "{}\n{}\n",
        p.wrap("31", &named("--- expected", expected_name)),
        p.wrap("32", &named("+++ actual", actual_name))
    );
    if e != a && e.len() == a.len() && e.iter().zip(&a).all(|(x, y)| x.trim_end() == y.trim_end()) {
        out.push_str("  (the lines differ only in spaces or tabs at their ends)\n");
    }
    let ed = edits(&e, &a);
    // The edits to show: each change with its context.
    let changed: Vec<usize> = (0..ed.len())
        .filter(|&k| !matches!(ed[k], Edit::Same(..)))
        .collect();
    if changed.is_empty() {
        let why = if expected.ends_with('\n') != actual.ends_with('\n') {
            if actual.ends_with('\n') {
                "the expected text has no line end at its end; the output has one"
            } else {
                "the output has no line end at its end; the expected text has one"
            }
        } else {
            "the texts differ in line ends (\\r\\n against \\n)"
        };
        out.push_str(&format!("  (the lines are the same: {why})\n"));
        return out;
    }
    let mut k = 0;
    while k < changed.len() {
        // A hunk: changes closer than twice the context join.
        let first = changed[k];
        let mut last = first;
        while k + 1 < changed.len() && changed[k + 1] - last <= 2 * CONTEXT + 1 {
            k += 1;
            last = changed[k];
        }
        k += 1;
        let (from, to) = (
            first.saturating_sub(CONTEXT),
            (last + CONTEXT + 1).min(ed.len()),
        );
        let (el, al) = ed[from..to]
            .iter()
            .fold((None, None), |(el, al), x| match *x {
                Edit::Same(i, j) => (el.or(Some(i)), al.or(Some(j))),
                Edit::Gone(i) => (el.or(Some(i)), al),
                Edit::New(j) => (el, al.or(Some(j))),
            });
        let at = |x: Option<usize>| x.map_or("-".into(), |x| (x + 1).to_string());
        out.push_str(&p.wrap(
            "36",
            &format!("@@ expected line {}, actual line {} @@", at(el), at(al)),
        ));
        out.push('\n');
        for x in &ed[from..to] {
            match *x {
                Edit::Same(i, _) => out.push_str(&format!("  {:>4} | {}\n", i + 1, e[i])),
                Edit::Gone(i) => {
                    out.push_str(&p.wrap("31", &format!("- {:>4} | {}", i + 1, e[i])));
                    out.push('\n');
                }
                Edit::New(j) => {
                    out.push_str(&p.wrap("32", &format!("+ {:>4} | {}", j + 1, a[j])));
                    out.push('\n');
                }
            }
        }
    }
    out
}

/// Text for an XML document: `&`, `<`, `>`, `"` and `'` escaped, and the
/// characters XML 1.0 cannot hold at all (control characters other than
/// tab, line feed and carriage return; U+FFFE, U+FFFF) written as U+FFFD.
pub fn xml_escape(text: &str) -> String {
    let mut s = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => s.push_str("&amp;"),
            '<' => s.push_str("&lt;"),
            '>' => s.push_str("&gt;"),
            '"' => s.push_str("&quot;"),
            '\'' => s.push_str("&apos;"),
            '\t' | '\n' => s.push(c),
            '\r' => s.push_str("&#13;"),
            c if (c as u32) < 0x20 || c == '\u{FFFE}' || c == '\u{FFFF}' => s.push('\u{FFFD}'),
            c => s.push(c),
        }
    }
    s
}

/// A JUnit XML report of a run of `adair test` (one `testsuite`, a
/// `testcase` per script named by its file, its folder as `classname`): a
/// failed comparison, a missing `.out` and a time limit are `failure`s, a
/// configuration error or a crashed run an `error`; what the script printed
/// is its `system-out`.
pub fn junit(results: &[CaseResult], suite: &str) -> String {
    let failures = results
        .iter()
        .filter(|r| {
            matches!(
                r.verdict,
                Verdict::Differs { .. } | Verdict::Missing { .. } | Verdict::TimedOut { .. }
            )
        })
        .count();
    let errors = results
        .iter()
        .filter(|r| matches!(r.verdict, Verdict::Config(_) | Verdict::Crashed(_)))
        .count();
    let time: f64 = results.iter().map(|r| r.seconds).sum();
    let mut x = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    x.push_str(&format!(
        "<testsuites name=\"{0}\" tests=\"{1}\" failures=\"{failures}\" errors=\"{errors}\" \
         time=\"{time:.3}\">\n  <testsuite name=\"{0}\" tests=\"{1}\" failures=\"{failures}\" \
         errors=\"{errors}\" skipped=\"0\" time=\"{time:.3}\">\n",
        xml_escape(suite),
        results.len()
    ));
    for r in results {
        let folder = match r.script.parent() {
            Some(d) if !d.as_os_str().is_empty() => d.to_string_lossy().into_owned(),
            _ => ".".into(),
        };
        x.push_str(&format!(
            "    <testcase classname=\"{}\" name=\"{}\" file=\"{}\" time=\"{:.3}\"",
            xml_escape(&folder),
            xml_escape(&shown_name(&r.script)),
            xml_escape(&r.script.to_string_lossy()),
            r.seconds
        ));
        let element = |kind: &str, ty: &str, message: &str, body: &str| {
            format!(
                "      <{kind} type=\"{ty}\" message=\"{}\">{}</{kind}>\n",
                xml_escape(message),
                xml_escape(body)
            )
        };
        let (inner, printed) = match &r.verdict {
            Verdict::Pass | Verdict::Blessed => (String::new(), None),
            Verdict::Differs { expected, actual } => (
                element(
                    "failure",
                    "differs",
                    &format!(
                        "the output differs from {}",
                        shown_name(&expected_path(&r.script))
                    ),
                    &diff(expected, actual),
                ),
                Some(actual),
            ),
            Verdict::Missing { actual } => (
                element(
                    "failure",
                    "missing",
                    &format!("no {}", shown_name(&expected_path(&r.script))),
                    "",
                ),
                Some(actual),
            ),
            Verdict::TimedOut { limit, partial } => (
                element(
                    "failure",
                    "timeout",
                    &format!("still running after {limit} s (wall clock)"),
                    "",
                ),
                partial.as_ref(),
            ),
            Verdict::Config(e) => (
                element("error", "configuration", "a configuration error", e),
                None,
            ),
            Verdict::Crashed(e) => (element("error", "crashed", "the run failed", e), None),
        };
        if inner.is_empty() && printed.is_none() {
            x.push_str("/>\n");
            continue;
        }
        x.push_str(">\n");
        x.push_str(&inner);
        if let Some(t) = printed {
            x.push_str(&format!(
                "      <system-out>{}</system-out>\n",
                xml_escape(t)
            ));
        }
        x.push_str("    </testcase>\n");
    }
    x.push_str("  </testsuite>\n</testsuites>\n");
    x
}
