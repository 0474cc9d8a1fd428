//! What `solve` and `sweep` print: named scalar fields and one table, rendered as
//! `name = value` lines plus an aligned table, as CSV with `#` comment lines, or as one JSON
//! object whose table is an object of columns.
//!
//! Numbers are written in Rust's shortest round-trip form, so every printed double reads back
//! to the same bits. JSON has no infinities: non-finite numbers and missing values are null.

use std::io::{self, Write};

use super::args::Format;

/// A printed value.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    Num(f64),
    Text(String),
    /// A value that does not exist (e.g. c of a failed solve).
    Missing,
    /// Named values printed together (e.g. the material's constants).
    Group(Vec<(&'static str, Value)>),
}

impl From<f64> for Value {
    fn from(v: f64) -> Self {
        Value::Num(v)
    }
}

impl From<&str> for Value {
    fn from(v: &str) -> Self {
        Value::Text(v.to_owned())
    }
}

/// One named field or table column: `key` in CSV and JSON, `label` for people.
#[derive(Clone, Copy, Debug)]
pub struct Name {
    pub key: &'static str,
    pub label: &'static str,
}

/// A [`Name`] whose label is its key.
pub const fn name(key: &'static str) -> Name {
    Name { key, label: key }
}

/// Scalar fields followed by one table.
#[derive(Debug)]
pub struct Report {
    pub fields: Vec<(Name, Value)>,
    /// The JSON key of the table.
    pub table_key: &'static str,
    pub columns: Vec<Name>,
    pub rows: Vec<Vec<Value>>,
}

impl Report {
    /// Writes the report in `format`.
    pub fn write(&self, format: Format, out: &mut impl Write) -> io::Result<()> {
        match format {
            Format::Table => self.write_table(out),
            Format::Csv => self.write_csv(out),
            Format::Json => self.write_json(out),
        }
    }

    fn write_table(&self, out: &mut impl Write) -> io::Result<()> {
        self.write_fields("", out)?;
        if self.rows.is_empty() {
            return Ok(());
        }
        let cells: Vec<Vec<String>> = self
            .rows
            .iter()
            .map(|row| row.iter().map(|v| text(v, "-")).collect())
            .collect();
        let widths: Vec<usize> = self
            .columns
            .iter()
            .enumerate()
            .map(|(j, c)| {
                cells
                    .iter()
                    .map(|r| r[j].len())
                    .fold(c.label.len(), usize::max)
            })
            .collect();
        let line = |out: &mut dyn Write, row: &mut dyn Iterator<Item = &str>| {
            let padded: Vec<String> = row.zip(&widths).map(|(s, w)| format!("{s:>w$}")).collect();
            writeln!(out, "{}", padded.join("  "))
        };
        writeln!(out)?;
        line(out, &mut self.columns.iter().map(|c| c.label))?;
        for row in &cells {
            line(out, &mut row.iter().map(String::as_str))?;
        }
        Ok(())
    }

    fn write_csv(&self, out: &mut impl Write) -> io::Result<()> {
        self.write_fields("# ", out)?;
        let keys: Vec<&str> = self.columns.iter().map(|c| c.key).collect();
        writeln!(out, "{}", keys.join(","))?;
        for row in &self.rows {
            let cells: Vec<String> = row.iter().map(|v| text(v, "")).collect();
            writeln!(out, "{}", cells.join(","))?;
        }
        Ok(())
    }

    /// `label = value` lines (groups: `label: key = value, ...`), each after `prefix`.
    fn write_fields(&self, prefix: &str, out: &mut impl Write) -> io::Result<()> {
        for (name, value) in &self.fields {
            let sep = if matches!(value, Value::Group(_)) {
                ":"
            } else {
                " ="
            };
            writeln!(out, "{prefix}{}{sep} {}", name.label, text(value, "-"))?;
        }
        Ok(())
    }

    fn write_json(&self, out: &mut impl Write) -> io::Result<()> {
        let mut members: Vec<(&str, String)> =
            self.fields.iter().map(|(n, v)| (n.key, json(v))).collect();
        let columns: Vec<(&str, String)> = self
            .columns
            .iter()
            .enumerate()
            .map(|(j, c)| {
                let values: Vec<String> = self.rows.iter().map(|r| json(&r[j])).collect();
                (c.key, format!("[{}]", values.join(", ")))
            })
            .collect();
        members.push((self.table_key, json_object(&columns)));
        writeln!(out, "{}", json_object(&members))
    }
}

/// A value as text; `missing` stands for [`Value::Missing`].
fn text(v: &Value, missing: &str) -> String {
    match v {
        Value::Num(x) => format!("{x:?}"),
        Value::Text(s) => s.clone(),
        Value::Missing => missing.to_owned(),
        Value::Group(items) => {
            let items: Vec<String> = items
                .iter()
                .map(|(k, v)| format!("{k} = {}", text(v, missing)))
                .collect();
            items.join(", ")
        }
    }
}

fn json(v: &Value) -> String {
    match v {
        Value::Num(x) if x.is_finite() => format!("{x:?}"),
        Value::Num(_) | Value::Missing => "null".to_owned(),
        Value::Text(s) => json_string(s),
        Value::Group(items) => {
            let members: Vec<(&str, String)> = items.iter().map(|(k, v)| (*k, json(v))).collect();
            json_object(&members)
        }
    }
}

fn json_object(members: &[(&str, String)]) -> String {
    let members: Vec<String> = members
        .iter()
        .map(|(k, v)| format!("{}: {v}", json_string(k)))
        .collect();
    format!("{{{}}}", members.join(", "))
}

/// A JSON string literal (RFC 8259 escapes).
fn json_string(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for ch in s.chars() {
        match ch {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if (c as u32) < 0x20 => out.push_str(&format!("\\u{:04x}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample() -> Report {
        Report {
            fields: vec![
                (name("mu"), 0.3.into()),
                (
                    Name {
                        key: "one_minus_c",
                        label: "1 - c",
                    },
                    1e-300.into(),
                ),
                (name("error_estimate"), f64::INFINITY.into()),
                (
                    name("material"),
                    Value::Group(vec![("E", 2.0.into()), ("nu", (-0.25).into())]),
                ),
                (name("note"), "say \"hi\"\\\n".into()),
            ],
            table_key: "points",
            columns: vec![name("x"), name("c")],
            rows: vec![
                vec![0.5.into(), Value::Missing],
                vec![(-1.0).into(), 0.1.into()],
            ],
        }
    }

    fn render(format: Format) -> String {
        let mut out = Vec::new();
        sample().write(format, &mut out).unwrap();
        String::from_utf8(out).unwrap()
    }

    #[test]
    fn json_round_trips_numbers_and_nulls_non_finite_values() {
        let v: serde_json::Value = serde_json::from_str(&render(Format::Json)).unwrap();
        assert_eq!(v["mu"].as_f64(), Some(0.3));
        assert_eq!(v["one_minus_c"].as_f64(), Some(1e-300));
        assert!(v["error_estimate"].is_null());
        assert_eq!(v["material"]["nu"].as_f64(), Some(-0.25));
        assert_eq!(v["note"].as_str(), Some("say \"hi\"\\\n"));
        assert_eq!(v["points"]["x"][1].as_f64(), Some(-1.0));
        assert!(v["points"]["c"][0].is_null());
    }

    #[test]
    fn table_and_csv_layouts() {
        let table = render(Format::Table);
        assert!(table.starts_with("mu = 0.3\n1 - c = 1e-300\nerror_estimate = inf\n"));
        assert!(table.contains("material: E = 2.0, nu = -0.25\n"));
        assert!(
            table.ends_with("\n   x    c\n 0.5    -\n-1.0  0.1\n"),
            "{table}"
        );
        let csv = render(Format::Csv);
        assert!(csv.starts_with("# mu = 0.3\n"));
        assert!(csv.ends_with("x,c\n0.5,\n-1.0,0.1\n"), "{csv}");
    }
}
