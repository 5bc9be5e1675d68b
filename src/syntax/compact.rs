//! Syntax trees in a compact binary form, so that a known text need not be
//! parsed again: the predefined library's files are kept parsed in
//! `stdlib/parsed/` (issue 32 item 4, start-up: parsing them was most of a
//! short program's run). The form is serde's data model written in order,
//! without names: integers as LEB128 (signed ones zigzagged), strings as a
//! length and their bytes, a sequence as its length and its elements, an
//! enumeration's variant as its index, a structure as its fields. A span
//! is its two offsets: its source is the one the tree is read for.
//!
//! Reading never panics: a form that does not fit the tree's types (another
//! version of adair, a damaged file) is `None`, and the text is parsed.

use crate::diag::FileId;
use serde::de::{self, DeserializeSeed, IntoDeserializer, Visitor};
use serde::ser::{self, Serialize};
use std::fmt;

/// The name serde gives `diag::Span` (chumsky's `SimpleSpan`).
const SPAN: &str = "SimpleSpan";

/// `value` in the compact form.
pub fn encode<T: Serialize>(value: &T) -> Option<Vec<u8>> {
    let mut w = Writer { out: Vec::new() };
    value.serialize(&mut w).ok()?;
    Some(w.out)
}

/// The tree `bytes` hold, its spans in source `file`; `None` unless the
/// bytes are exactly one `T`.
pub fn decode<'de, T: de::Deserialize<'de>>(bytes: &'de [u8], file: FileId) -> Option<T> {
    let mut r = Reader {
        bytes,
        at: 0,
        file,
        depth: 0,
    };
    let v = T::deserialize(&mut r).ok()?;
    (r.at == bytes.len()).then_some(v)
}

/// Why a tree was not written or read (never shown: the caller falls back).
#[derive(Debug)]
pub struct Error;

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("not a compact syntax tree")
    }
}

impl std::error::Error for Error {}

impl ser::Error for Error {
    fn custom<T: fmt::Display>(_: T) -> Self {
        Error
    }
}

impl de::Error for Error {
    fn custom<T: fmt::Display>(_: T) -> Self {
        Error
    }
}

type Result<T> = std::result::Result<T, Error>;

struct Writer {
    out: Vec<u8>,
}

impl Writer {
    fn uint(&mut self, mut v: u64) {
        loop {
            let b = (v & 0x7f) as u8;
            v >>= 7;
            if v == 0 {
                self.out.push(b);
                return;
            }
            self.out.push(b | 0x80);
        }
    }
    fn int(&mut self, v: i64) {
        self.uint(((v << 1) ^ (v >> 63)) as u64);
    }
    fn len(&mut self, n: Option<usize>) -> Result<()> {
        self.uint(n.ok_or(Error)? as u64);
        Ok(())
    }
}

impl<'a> ser::Serializer for &'a mut Writer {
    type Ok = ();
    type Error = Error;
    type SerializeSeq = Self;
    type SerializeTuple = Self;
    type SerializeTupleStruct = Self;
    type SerializeTupleVariant = Self;
    type SerializeMap = Self;
    type SerializeStruct = Fields<'a>;
    type SerializeStructVariant = Self;

    fn is_human_readable(&self) -> bool {
        false
    }
    fn serialize_bool(self, v: bool) -> Result<()> {
        self.out.push(v as u8);
        Ok(())
    }
    fn serialize_i8(self, v: i8) -> Result<()> {
        self.int(v.into());
        Ok(())
    }
    fn serialize_i16(self, v: i16) -> Result<()> {
        self.int(v.into());
        Ok(())
    }
    fn serialize_i32(self, v: i32) -> Result<()> {
        self.int(v.into());
        Ok(())
    }
    fn serialize_i64(self, v: i64) -> Result<()> {
        self.int(v);
        Ok(())
    }
    fn serialize_u8(self, v: u8) -> Result<()> {
        self.uint(v.into());
        Ok(())
    }
    fn serialize_u16(self, v: u16) -> Result<()> {
        self.uint(v.into());
        Ok(())
    }
    fn serialize_u32(self, v: u32) -> Result<()> {
        self.uint(v.into());
        Ok(())
    }
    fn serialize_u64(self, v: u64) -> Result<()> {
        self.uint(v);
        Ok(())
    }
    fn serialize_f32(self, v: f32) -> Result<()> {
        self.out.extend_from_slice(&v.to_le_bytes());
        Ok(())
    }
    fn serialize_f64(self, v: f64) -> Result<()> {
        self.out.extend_from_slice(&v.to_le_bytes());
        Ok(())
    }
    fn serialize_char(self, v: char) -> Result<()> {
        self.uint(v.into());
        Ok(())
    }
    fn serialize_str(self, v: &str) -> Result<()> {
        self.serialize_bytes(v.as_bytes())
    }
    fn serialize_bytes(self, v: &[u8]) -> Result<()> {
        self.uint(v.len() as u64);
        self.out.extend_from_slice(v);
        Ok(())
    }
    fn serialize_none(self) -> Result<()> {
        self.out.push(0);
        Ok(())
    }
    fn serialize_some<T: ?Sized + Serialize>(self, v: &T) -> Result<()> {
        self.out.push(1);
        v.serialize(self)
    }
    fn serialize_unit(self) -> Result<()> {
        Ok(())
    }
    fn serialize_unit_struct(self, _: &'static str) -> Result<()> {
        Ok(())
    }
    fn serialize_unit_variant(self, _: &'static str, i: u32, _: &'static str) -> Result<()> {
        self.uint(i.into());
        Ok(())
    }
    fn serialize_newtype_struct<T: ?Sized + Serialize>(self, _: &'static str, v: &T) -> Result<()> {
        v.serialize(self)
    }
    fn serialize_newtype_variant<T: ?Sized + Serialize>(
        self,
        _: &'static str,
        i: u32,
        _: &'static str,
        v: &T,
    ) -> Result<()> {
        self.uint(i.into());
        v.serialize(self)
    }
    fn serialize_seq(self, n: Option<usize>) -> Result<Self> {
        self.len(n)?;
        Ok(self)
    }
    fn serialize_tuple(self, _: usize) -> Result<Self> {
        Ok(self)
    }
    fn serialize_tuple_struct(self, _: &'static str, _: usize) -> Result<Self> {
        Ok(self)
    }
    fn serialize_tuple_variant(
        self,
        _: &'static str,
        i: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Self> {
        self.uint(i.into());
        Ok(self)
    }
    fn serialize_map(self, n: Option<usize>) -> Result<Self> {
        self.len(n)?;
        Ok(self)
    }
    fn serialize_struct(self, name: &'static str, _: usize) -> Result<Fields<'a>> {
        Ok(Fields {
            w: self,
            span: name == SPAN,
        })
    }
    fn serialize_struct_variant(
        self,
        _: &'static str,
        i: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Self> {
        self.uint(i.into());
        Ok(self)
    }
}

impl ser::SerializeSeq for &mut Writer {
    type Ok = ();
    type Error = Error;
    fn serialize_element<T: ?Sized + Serialize>(&mut self, v: &T) -> Result<()> {
        v.serialize(&mut **self)
    }
    fn end(self) -> Result<()> {
        Ok(())
    }
}

impl ser::SerializeTuple for &mut Writer {
    type Ok = ();
    type Error = Error;
    fn serialize_element<T: ?Sized + Serialize>(&mut self, v: &T) -> Result<()> {
        v.serialize(&mut **self)
    }
    fn end(self) -> Result<()> {
        Ok(())
    }
}

impl ser::SerializeTupleStruct for &mut Writer {
    type Ok = ();
    type Error = Error;
    fn serialize_field<T: ?Sized + Serialize>(&mut self, v: &T) -> Result<()> {
        v.serialize(&mut **self)
    }
    fn end(self) -> Result<()> {
        Ok(())
    }
}

impl ser::SerializeTupleVariant for &mut Writer {
    type Ok = ();
    type Error = Error;
    fn serialize_field<T: ?Sized + Serialize>(&mut self, v: &T) -> Result<()> {
        v.serialize(&mut **self)
    }
    fn end(self) -> Result<()> {
        Ok(())
    }
}

impl ser::SerializeMap for &mut Writer {
    type Ok = ();
    type Error = Error;
    fn serialize_key<T: ?Sized + Serialize>(&mut self, k: &T) -> Result<()> {
        k.serialize(&mut **self)
    }
    fn serialize_value<T: ?Sized + Serialize>(&mut self, v: &T) -> Result<()> {
        v.serialize(&mut **self)
    }
    fn end(self) -> Result<()> {
        Ok(())
    }
}

impl ser::SerializeStructVariant for &mut Writer {
    type Ok = ();
    type Error = Error;
    fn serialize_field<T: ?Sized + Serialize>(&mut self, _: &'static str, v: &T) -> Result<()> {
        v.serialize(&mut **self)
    }
    fn end(self) -> Result<()> {
        Ok(())
    }
}

/// A structure's fields; a span's source is left out.
pub struct Fields<'a> {
    w: &'a mut Writer,
    span: bool,
}

impl ser::SerializeStruct for Fields<'_> {
    type Ok = ();
    type Error = Error;
    fn serialize_field<T: ?Sized + Serialize>(&mut self, key: &'static str, v: &T) -> Result<()> {
        if self.span && key == "context" {
            return Ok(());
        }
        v.serialize(&mut *self.w)
    }
    fn end(self) -> Result<()> {
        Ok(())
    }
}

/// Nesting past this is not a tree adair wrote (the recursive reader
/// must not overflow the stack on a damaged form).
const MAX_DEPTH: u32 = 2_000;

struct Reader<'de> {
    bytes: &'de [u8],
    at: usize,
    file: FileId,
    depth: u32,
}

impl<'de> Reader<'de> {
    fn byte(&mut self) -> Result<u8> {
        let b = *self.bytes.get(self.at).ok_or(Error)?;
        self.at += 1;
        Ok(b)
    }
    fn take(&mut self, n: usize) -> Result<&'de [u8]> {
        let end = self.at.checked_add(n).ok_or(Error)?;
        let s = self.bytes.get(self.at..end).ok_or(Error)?;
        self.at = end;
        Ok(s)
    }
    fn uint(&mut self) -> Result<u64> {
        let mut v = 0u64;
        for shift in (0..64).step_by(7) {
            let b = self.byte()?;
            v |= u64::from(b & 0x7f).checked_shl(shift).ok_or(Error)?;
            if b & 0x80 == 0 {
                return Ok(v);
            }
        }
        Err(Error)
    }
    fn int(&mut self) -> Result<i64> {
        let u = self.uint()?;
        Ok(((u >> 1) as i64) ^ -((u & 1) as i64))
    }
    fn len(&mut self) -> Result<usize> {
        let n = usize::try_from(self.uint()?).map_err(|_| Error)?;
        // Every element takes a byte at least.
        if n > self.bytes.len() - self.at {
            return Err(Error);
        }
        Ok(n)
    }
    fn str(&mut self) -> Result<&'de str> {
        let n = self.len()?;
        std::str::from_utf8(self.take(n)?).map_err(|_| Error)
    }
    fn nested<T>(&mut self, f: impl FnOnce(&mut Self) -> Result<T>) -> Result<T> {
        if self.depth >= MAX_DEPTH {
            return Err(Error);
        }
        self.depth += 1;
        let r = f(self);
        self.depth -= 1;
        r
    }
}

macro_rules! read_int {
    ($($f:ident $visit:ident $t:ty, $read:ident;)*) => {$(
        fn $f<V: Visitor<'de>>(self, v: V) -> Result<V::Value> {
            let x = <$t>::try_from(self.$read()?).map_err(|_| Error)?;
            v.$visit(x)
        }
    )*};
}

impl<'de> de::Deserializer<'de> for &mut Reader<'de> {
    type Error = Error;

    fn is_human_readable(&self) -> bool {
        false
    }
    fn deserialize_any<V: Visitor<'de>>(self, _: V) -> Result<V::Value> {
        Err(Error)
    }
    fn deserialize_ignored_any<V: Visitor<'de>>(self, _: V) -> Result<V::Value> {
        Err(Error)
    }
    fn deserialize_bool<V: Visitor<'de>>(self, v: V) -> Result<V::Value> {
        match self.byte()? {
            0 => v.visit_bool(false),
            1 => v.visit_bool(true),
            _ => Err(Error),
        }
    }
    read_int! {
        deserialize_i8 visit_i8 i8, int;
        deserialize_i16 visit_i16 i16, int;
        deserialize_i32 visit_i32 i32, int;
        deserialize_i64 visit_i64 i64, int;
        deserialize_u8 visit_u8 u8, uint;
        deserialize_u16 visit_u16 u16, uint;
        deserialize_u32 visit_u32 u32, uint;
        deserialize_u64 visit_u64 u64, uint;
    }
    fn deserialize_f32<V: Visitor<'de>>(self, v: V) -> Result<V::Value> {
        let b = self.take(4)?.try_into().map_err(|_| Error)?;
        v.visit_f32(f32::from_le_bytes(b))
    }
    fn deserialize_f64<V: Visitor<'de>>(self, v: V) -> Result<V::Value> {
        let b = self.take(8)?.try_into().map_err(|_| Error)?;
        v.visit_f64(f64::from_le_bytes(b))
    }
    fn deserialize_char<V: Visitor<'de>>(self, v: V) -> Result<V::Value> {
        let c = u32::try_from(self.uint()?).map_err(|_| Error)?;
        v.visit_char(char::from_u32(c).ok_or(Error)?)
    }
    fn deserialize_str<V: Visitor<'de>>(self, v: V) -> Result<V::Value> {
        v.visit_borrowed_str(self.str()?)
    }
    fn deserialize_string<V: Visitor<'de>>(self, v: V) -> Result<V::Value> {
        v.visit_borrowed_str(self.str()?)
    }
    fn deserialize_bytes<V: Visitor<'de>>(self, v: V) -> Result<V::Value> {
        let n = self.len()?;
        v.visit_borrowed_bytes(self.take(n)?)
    }
    fn deserialize_byte_buf<V: Visitor<'de>>(self, v: V) -> Result<V::Value> {
        self.deserialize_bytes(v)
    }
    fn deserialize_option<V: Visitor<'de>>(self, v: V) -> Result<V::Value> {
        match self.byte()? {
            0 => v.visit_none(),
            1 => self.nested(|r| v.visit_some(r)),
            _ => Err(Error),
        }
    }
    fn deserialize_unit<V: Visitor<'de>>(self, v: V) -> Result<V::Value> {
        v.visit_unit()
    }
    fn deserialize_unit_struct<V: Visitor<'de>>(self, _: &'static str, v: V) -> Result<V::Value> {
        v.visit_unit()
    }
    fn deserialize_newtype_struct<V: Visitor<'de>>(
        self,
        _: &'static str,
        v: V,
    ) -> Result<V::Value> {
        self.nested(|r| v.visit_newtype_struct(r))
    }
    fn deserialize_seq<V: Visitor<'de>>(self, v: V) -> Result<V::Value> {
        let n = self.len()?;
        self.nested(|r| v.visit_seq(Items { r, left: n }))
    }
    fn deserialize_tuple<V: Visitor<'de>>(self, n: usize, v: V) -> Result<V::Value> {
        self.nested(|r| v.visit_seq(Items { r, left: n }))
    }
    fn deserialize_tuple_struct<V: Visitor<'de>>(
        self,
        _: &'static str,
        n: usize,
        v: V,
    ) -> Result<V::Value> {
        self.deserialize_tuple(n, v)
    }
    fn deserialize_map<V: Visitor<'de>>(self, v: V) -> Result<V::Value> {
        let n = self.len()?;
        self.nested(|r| v.visit_map(Items { r, left: n }))
    }
    fn deserialize_struct<V: Visitor<'de>>(
        self,
        name: &'static str,
        fields: &'static [&'static str],
        v: V,
    ) -> Result<V::Value> {
        if name == SPAN {
            return v.visit_seq(SpanFields { r: self, next: 0 });
        }
        self.deserialize_tuple(fields.len(), v)
    }
    fn deserialize_enum<V: Visitor<'de>>(
        self,
        _: &'static str,
        _: &'static [&'static str],
        v: V,
    ) -> Result<V::Value> {
        self.nested(|r| v.visit_enum(r))
    }
    fn deserialize_identifier<V: Visitor<'de>>(self, v: V) -> Result<V::Value> {
        let i = u32::try_from(self.uint()?).map_err(|_| Error)?;
        v.visit_u32(i)
    }
}

/// The elements of a sequence, tuple or structure, or a map's entries.
struct Items<'a, 'de> {
    r: &'a mut Reader<'de>,
    left: usize,
}

impl<'de> de::SeqAccess<'de> for Items<'_, 'de> {
    type Error = Error;
    fn next_element_seed<T: DeserializeSeed<'de>>(&mut self, seed: T) -> Result<Option<T::Value>> {
        if self.left == 0 {
            return Ok(None);
        }
        self.left -= 1;
        seed.deserialize(&mut *self.r).map(Some)
    }
    fn size_hint(&self) -> Option<usize> {
        Some(self.left)
    }
}

impl<'de> de::MapAccess<'de> for Items<'_, 'de> {
    type Error = Error;
    fn next_key_seed<K: DeserializeSeed<'de>>(&mut self, seed: K) -> Result<Option<K::Value>> {
        if self.left == 0 {
            return Ok(None);
        }
        self.left -= 1;
        seed.deserialize(&mut *self.r).map(Some)
    }
    fn next_value_seed<T: DeserializeSeed<'de>>(&mut self, seed: T) -> Result<T::Value> {
        seed.deserialize(&mut *self.r)
    }
    fn size_hint(&self) -> Option<usize> {
        Some(self.left)
    }
}

/// A span's fields: its offsets from the form, its source the reader's.
struct SpanFields<'a, 'de> {
    r: &'a mut Reader<'de>,
    next: u8,
}

impl<'de> de::SeqAccess<'de> for SpanFields<'_, 'de> {
    type Error = Error;
    fn next_element_seed<T: DeserializeSeed<'de>>(&mut self, seed: T) -> Result<Option<T::Value>> {
        self.next += 1;
        match self.next {
            1 | 2 => seed.deserialize(&mut *self.r).map(Some),
            3 => seed
                .deserialize(IntoDeserializer::<Error>::into_deserializer(self.r.file))
                .map(Some),
            _ => Ok(None),
        }
    }
}

impl<'de> de::EnumAccess<'de> for &mut Reader<'de> {
    type Error = Error;
    type Variant = Self;
    fn variant_seed<V: DeserializeSeed<'de>>(self, seed: V) -> Result<(V::Value, Self)> {
        let i = u32::try_from(self.uint()?).map_err(|_| Error)?;
        let v = seed.deserialize(IntoDeserializer::<Error>::into_deserializer(i))?;
        Ok((v, self))
    }
}

impl<'de> de::VariantAccess<'de> for &mut Reader<'de> {
    type Error = Error;
    fn unit_variant(self) -> Result<()> {
        Ok(())
    }
    fn newtype_variant_seed<T: DeserializeSeed<'de>>(self, seed: T) -> Result<T::Value> {
        seed.deserialize(self)
    }
    fn tuple_variant<V: Visitor<'de>>(self, n: usize, v: V) -> Result<V::Value> {
        de::Deserializer::deserialize_tuple(self, n, v)
    }
    fn struct_variant<V: Visitor<'de>>(
        self,
        fields: &'static [&'static str],
        v: V,
    ) -> Result<V::Value> {
        de::Deserializer::deserialize_tuple(self, fields.len(), v)
    }
}

#[cfg(test)]
mod tests {
    use super::{decode, encode};
    use crate::syntax::ast::CompilationUnit;

    fn parsed(text: &str, file: u32) -> CompilationUnit {
        let (unit, diags) = crate::syntax::parse_source(text, file);
        assert!(diags.is_empty(), "{diags:?}");
        unit.expect("parses")
    }

    /// A tree read back is the tree written, its spans in the reader's
    /// source.
    #[test]
    fn a_tree_comes_back_whole() {
        let text = "with Ada.Text_IO; use Ada.Text_IO;\n\
            procedure P is\n\
               type Color is (Red, 'x', Blue);\n\
               X : Float := 2.5E-3; N : constant := 16#FF#;\n\
               S : String := \"a\"\"b\" & Character'Val (200) & 'y';\n\
               function F (A : in out Integer) return Boolean is (A > -3);\n\
            begin\n\
               for I in reverse 1 .. 10 loop\n\
                  if X < 1.0 or else not F (N) then Put_Line (S (1 .. 2)); end if;\n\
               end loop;\n\
               case N is when 1 | 2 => null; when others => raise Program_Error; end case;\n\
            exception when E : others => null;\n\
            end P;\n";
        let unit = parsed(text, 0);
        let bytes = encode(&unit).expect("encodes");
        assert_eq!(decode::<CompilationUnit>(&bytes, 0).as_ref(), Some(&unit));
        // In another source, every span moves there.
        assert_eq!(decode::<CompilationUnit>(&bytes, 7), Some(parsed(text, 7)));
    }

    /// A damaged form is refused, never a panic.
    #[test]
    fn a_damaged_form_is_refused() {
        let unit = parsed("package P is X : Integer := 1; end P;", 0);
        let bytes = encode(&unit).expect("encodes");
        for cut in 0..bytes.len() {
            assert!(
                decode::<CompilationUnit>(&bytes[..cut], 0).is_none(),
                "{cut}"
            );
        }
        let mut longer = bytes.clone();
        longer.push(0);
        assert!(decode::<CompilationUnit>(&longer, 0).is_none());
        for i in 0..bytes.len() {
            for b in [0x00, 0x7f, 0x80, 0xff] {
                let mut bad = bytes.clone();
                bad[i] = b;
                let _ = decode::<CompilationUnit>(&bad, 0);
            }
        }
        let deep = vec![0x81u8; 100_000];
        assert!(decode::<CompilationUnit>(&deep, 0).is_none());
    }
}
