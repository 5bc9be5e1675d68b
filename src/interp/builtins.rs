//! Native bodies of the predefined library's imported subprograms
//! (`with Import, External_Name => "..."` in `stdlib/`).

use super::value::{self, Value};
use super::{Flow, Native, R, Run};
use crate::check;
use crate::diag::Span;

/// The native bound to an import name.
pub fn lookup(name: &str) -> Option<Native> {
    TABLE.iter().find(|(n, _)| *n == name).map(|(_, f)| *f)
}

pub fn known(name: &str) -> bool {
    lookup(name).is_some()
}

const TABLE: &[(&str, Native)] = &[
    // SERIAL_IO (the AdaIR package): terminals map to standard output.
    ("PutS_String", |r, a, _| {
        r.m.write_str(&a[1].text());
        Ok(None)
    }),
    ("PutS_Integer", |r, a, _| {
        r.m.write_str(&value::image_int(a[1].int()));
        Ok(None)
    }),
    ("New_LineS", |r, _, _| {
        r.m.write_str("\n");
        Ok(None)
    }),
    ("Get_LineS", |r, _, span| read_line(r, span).map(|_| None)),
    ("Get_LineS_Text", get_lines_text),
    ("put_fixed", |r, a, _| {
        r.m.write_str(&value::put_float(a[0].real(), 7, 3, 0));
        Ok(None)
    }),
    ("put_string", put_string),
    ("put_char", put_char),
    ("put_line", put_line),
    ("new_line", new_line),
    ("get_line_fn", get_line_fn),
    ("get_line", get_line),
    ("put_int", put_int),
    ("put_float", put_float),
    ("sqrt", sqrt),
    ("sin", |_, a, _| f1(a, f64::sin)),
    ("cos", |_, a, _| f1(a, f64::cos)),
    ("tan", |_, a, _| f1(a, f64::tan)),
    ("cot", cot),
    ("arcsin", arcsin),
    ("arccos", arccos),
    ("arctan", arctan),
    ("exp", |_, a, _| f1(a, f64::exp)),
    ("log", log),
    ("log_base", log_base),
    ("float_pow", float_pow),
    ("exception_name", exception_name),
    ("exception_message", exception_message),
    ("exception_information", exception_information),
    ("clock", |r, _, _| {
        Ok(Some(Value::Real(value::whole_ns(r.m.clock.now()))))
    }),
    // Times, spans and durations are whole nanoseconds (value::whole_ns).
    ("time_diff", |_, a, _| {
        Ok(Some(Value::Real(value::whole_ns(
            a[0].real() - a[1].real(),
        ))))
    }),
    // Ada.Real_Time's `Span / Span`: whole nanoseconds divided, truncated
    // toward zero (GNAT's fixed point: 300 ms / 100 ms = 3, not 2.999...).
    ("span_quotient", |r, a, span| {
        let ns = |v: &Value| (v.real() * 1e9).round() as i128;
        let (x, y) = (ns(&a[0]), ns(&a[1]));
        if y == 0 {
            return Err(r.check_failed("divide by zero", span));
        }
        match i32::try_from(x / y) {
            Ok(q) => Ok(Some(Value::Int(q as i64))),
            Err(_) => Err(r.check_failed("overflow check failed", span)),
        }
    }),
    ("time_add", |_, a, _| {
        Ok(Some(Value::Real(value::whole_ns(
            a[0].real() + a[1].real(),
        ))))
    }),
    ("time_sub", |_, a, _| {
        Ok(Some(Value::Real(value::whole_ns(
            a[0].real() - a[1].real(),
        ))))
    }),
    ("time_lt", |_, a, _| {
        Ok(Some(Value::Int((a[0].real() < a[1].real()) as i64)))
    }),
    ("time_le", |_, a, _| {
        Ok(Some(Value::Int((a[0].real() <= a[1].real()) as i64)))
    }),
    ("time_gt", |_, a, _| {
        Ok(Some(Value::Int((a[0].real() > a[1].real()) as i64)))
    }),
    ("time_ge", |_, a, _| {
        Ok(Some(Value::Int((a[0].real() >= a[1].real()) as i64)))
    }),
    ("seconds", |_, a, _| {
        Ok(Some(Value::Real(value::whole_ns(
            a[0].real().rem_euclid(86_400.0),
        ))))
    }),
];

fn f1(a: &[Value], f: fn(f64) -> f64) -> R<Option<Value>> {
    Ok(Some(Value::Real(f(a[0].real()))))
}

fn argument_error(r: &Run, what: &str, span: Span) -> Flow {
    let e = r.exc_by_name("ADA.NUMERICS.ARGUMENT_ERROR");
    r.raise(e, what.to_string(), span)
}

fn sqrt(r: &mut Run, a: &mut [Value], span: Span) -> R<Option<Value>> {
    let x = a[0].real();
    if x < 0.0 {
        return Err(argument_error(r, "Sqrt of a negative number", span));
    }
    Ok(Some(Value::Real(x.sqrt())))
}

fn arcsin(r: &mut Run, a: &mut [Value], span: Span) -> R<Option<Value>> {
    let x = a[0].real();
    if x.abs() > 1.0 {
        return Err(argument_error(r, "Arcsin outside -1.0 .. 1.0", span));
    }
    Ok(Some(Value::Real(x.asin())))
}

fn arccos(r: &mut Run, a: &mut [Value], span: Span) -> R<Option<Value>> {
    let x = a[0].real();
    if x.abs() > 1.0 {
        return Err(argument_error(r, "Arccos outside -1.0 .. 1.0", span));
    }
    Ok(Some(Value::Real(x.acos())))
}

fn log(r: &mut Run, a: &mut [Value], span: Span) -> R<Option<Value>> {
    let x = a[0].real();
    if x < 0.0 {
        return Err(argument_error(r, "Log of a negative number", span));
    }
    if x == 0.0 {
        return Err(pole(r, "Log of zero", span));
    }
    Ok(Some(Value::Real(x.ln())))
}

/// RM A.5.1: a pole of the function raises Constraint_Error.
fn pole(r: &Run, what: &str, span: Span) -> Flow {
    r.raise(check::CONSTRAINT_ERROR, what.to_string(), span)
}

fn cot(r: &mut Run, a: &mut [Value], span: Span) -> R<Option<Value>> {
    let x = a[0].real();
    if x == 0.0 {
        return Err(pole(r, "Cot of zero", span));
    }
    Ok(Some(Value::Real(1.0 / x.tan())))
}

fn arctan(r: &mut Run, a: &mut [Value], span: Span) -> R<Option<Value>> {
    let (y, x) = (a[0].real(), a[1].real());
    if y == 0.0 && x == 0.0 {
        return Err(argument_error(r, "Arctan with both arguments zero", span));
    }
    Ok(Some(Value::Real(y.atan2(x))))
}

fn log_base(r: &mut Run, a: &mut [Value], span: Span) -> R<Option<Value>> {
    let (x, b) = (a[0].real(), a[1].real());
    if x < 0.0 || b <= 0.0 || b == 1.0 {
        return Err(argument_error(r, "Log with a bad argument or base", span));
    }
    if x == 0.0 {
        return Err(pole(r, "Log of zero", span));
    }
    Ok(Some(Value::Real(x.ln() / b.ln())))
}

fn float_pow(r: &mut Run, a: &mut [Value], span: Span) -> R<Option<Value>> {
    let (x, y) = (a[0].real(), a[1].real());
    if x < 0.0 || (x == 0.0 && y == 0.0) {
        return Err(argument_error(
            r,
            "\"**\" with a negative base or 0.0 ** 0.0",
            span,
        ));
    }
    if x == 0.0 && y < 0.0 {
        return Err(pole(r, "\"**\" of 0.0 to a negative power", span));
    }
    Ok(Some(Value::Real(x.powf(y))))
}

fn put_string(r: &mut Run, a: &mut [Value], _: Span) -> R<Option<Value>> {
    let s = a[0].text();
    r.m.write_str(&s);
    Ok(None)
}

fn put_char(r: &mut Run, a: &mut [Value], _: Span) -> R<Option<Value>> {
    let c = char::from_u32(a[0].int() as u32).unwrap_or('?');
    r.m.write_str(&c.to_string());
    Ok(None)
}

fn put_line(r: &mut Run, a: &mut [Value], _: Span) -> R<Option<Value>> {
    let mut s = a[0].text();
    s.push('\n');
    r.m.write_str(&s);
    Ok(None)
}

fn new_line(r: &mut Run, a: &mut [Value], _: Span) -> R<Option<Value>> {
    for _ in 0..a[0].int().max(0) {
        r.m.write_str("\n");
    }
    Ok(None)
}

pub fn read_line(r: &mut Run, span: Span) -> R<String> {
    let _ = r.m.out.flush();
    r.m.col = 0;
    if let Some(rest) = r.m.line_rest.take() {
        return Ok(rest);
    }
    let mut line = String::new();
    match r.m.input.read_line(&mut line) {
        Ok(0) | Err(_) => Err(r.raise(check::END_ERROR, "end of file", span)),
        Ok(_) => {
            while line.ends_with('\n') || line.ends_with('\r') {
                line.pop();
            }
            Ok(line)
        }
    }
}

fn get_line_fn(r: &mut Run, _: &mut [Value], span: Span) -> R<Option<Value>> {
    let l = read_line(r, span)?;
    Ok(Some(Value::str(&l)))
}

/// `Get_Line (Item, Last)`: fills Item from its first index, Last is the last
/// index written. As in Ada (RM A.10.7): a longer line leaves its rest for
/// the next read; a line that fills Item exactly leaves its terminator, so
/// the next `Get_Line` gives an empty line.
pub fn get_line(r: &mut Run, a: &mut [Value], span: Span) -> R<Option<Value>> {
    let l = read_line(r, span)?;
    let Value::Arr(arr) = &mut a[0] else {
        return Ok(None);
    };
    let first = arr.bounds()[0].0;
    let room = arr.len_all();
    let chars: Vec<char> = l.chars().collect();
    let n = chars.len().min(room);
    for (k, c) in chars[..n].iter().enumerate() {
        arr.set(k, Value::Int(*c as i64));
    }
    if chars.len() >= room {
        r.m.line_rest = Some(chars[n..].iter().collect());
    }
    a[1] = Value::Int(first + n as i64 - 1);
    Ok(None)
}

use std::io::Write as _;

fn put_int(r: &mut Run, a: &mut [Value], _: Span) -> R<Option<Value>> {
    let (v, width, base) = (a[0].int(), a[1].int().max(0) as usize, a[2].int());
    let s = if base == 10 || !(2..=16).contains(&base) {
        v.to_string()
    } else {
        let mut digits = String::new();
        let mut x = v.unsigned_abs();
        if x == 0 {
            digits.push('0');
        }
        while x > 0 {
            digits.insert(
                0,
                std::char::from_digit((x % base as u64) as u32, base as u32)
                    .unwrap_or('?')
                    .to_ascii_uppercase(),
            );
            x /= base as u64;
        }
        format!("{}{base}#{digits}#", if v < 0 { "-" } else { "" })
    };
    r.m.write_str(&value::pad_left(&s, width));
    Ok(None)
}

fn put_float(r: &mut Run, a: &mut [Value], _: Span) -> R<Option<Value>> {
    let s = value::put_float(
        a[0].real(),
        a[1].int().max(0) as usize,
        a[2].int().max(0) as usize,
        a[3].int().max(0) as usize,
    );
    r.m.write_str(&s);
    Ok(None)
}

fn occurrence(a: &[Value]) -> Option<&super::Occurrence> {
    match &a[0] {
        Value::Occ(o) => Some(o),
        _ => None,
    }
}

fn exception_name(r: &mut Run, a: &mut [Value], _: Span) -> R<Option<Value>> {
    let name = occurrence(a)
        .map(|o| r.c.excs[o.exc as usize].name.clone())
        .unwrap_or_default();
    Ok(Some(Value::str(&name)))
}

fn exception_message(_: &mut Run, a: &mut [Value], _: Span) -> R<Option<Value>> {
    let m = occurrence(a).map(|o| o.message.clone()).unwrap_or_default();
    Ok(Some(Value::str(&m)))
}

fn exception_information(r: &mut Run, a: &mut [Value], _: Span) -> R<Option<Value>> {
    let s = occurrence(a)
        .map(|o| {
            let name = &r.c.excs[o.exc as usize].name;
            if o.message.is_empty() {
                format!("raised {name}\n")
            } else {
                format!("raised {name} : {}\n", o.message)
            }
        })
        .unwrap_or_default();
    Ok(Some(Value::str(&s)))
}

/// `Get_LineS (Term, Text, Last)`: `Get_Line` on standard input.
fn get_lines_text(r: &mut Run, a: &mut [Value], span: Span) -> R<Option<Value>> {
    let mut args = [a[1].clone(), a[2].clone()];
    get_line(r, &mut args, span)?;
    let [text, last] = args;
    a[1] = text;
    a[2] = last;
    Ok(None)
}
