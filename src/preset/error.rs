//! Where a preset is at fault: file:line:column for its TOML and for its semantic checks.

/// A preset that cannot be used: where, and why ("file:line:column: message").
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{origin}{}: {message}", at_position(*.position))]
pub struct PresetError {
    /// A file path, or `embedded:NAME`.
    pub origin: String,
    /// 1-based line and column, when known.
    pub position: Option<(usize, usize)>,
    /// What is wrong, one line (the field's table and key first for a semantic check).
    pub message: String,
}

/// ":line:column" after a file's name, when known.
fn at_position(position: Option<(usize, usize)>) -> String {
    position.map_or_else(String::new, |(l, c)| format!(":{l}:{c}"))
}

/// 1-based (line, column) of a byte offset.
pub(crate) fn line_col(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, col)
}

/// A message for one line of a terminal: the line breaks of a TOML message become spaces, and
/// other control characters (which a quoted key such as `"a\rb"` or `"\u001b[2J"` carries
/// into "unknown field" messages) are escaped, so that they neither break the line nor reach
/// the terminal as commands.
pub(crate) fn one_line(message: &str) -> String {
    message
        .trim()
        .chars()
        .map(|c| match c {
            '\n' => " ".to_string(),
            c if c.is_control() => c.escape_default().to_string(),
            c => c.to_string(),
        })
        .collect()
}

/// A field that fails the semantic checks: its table ("" at the top level), the layer's index
/// for `material.layers`, its key, and why.
pub(super) struct Bad {
    pub(super) table: &'static str,
    pub(super) layer: Option<usize>,
    pub(super) key: &'static str,
    pub(super) message: String,
}

/// Where a semantic error points: the key, from the spans of the parsed document, so that
/// every TOML spelling (headers with comments, dotted keys, inline tables, quoted keys) is
/// found; when the key is missing (a required field), the table that lacks it; when that is
/// missing too, the start of the file (tests: `every_error_has_a_position_and_one_line`).
pub(super) fn locate(text: &str, bad: &Bad) -> (usize, usize) {
    use toml::de::{DeTable, DeValue};
    let Ok(doc) = DeTable::parse(text) else {
        return (1, 1);
    };
    let mut offset = 0;
    let mut table: &DeTable = doc.get_ref();
    let path = bad.table.split('.').filter(|s| !s.is_empty());
    for segment in path.chain([bad.key]) {
        let Some((key, value)) = table.get_key_value(segment) else {
            break;
        };
        offset = key.span().start;
        let value = match (value.get_ref(), bad.layer) {
            (DeValue::Array(layers), Some(i)) => match layers.get(i) {
                Some(layer) => {
                    offset = layer.span().start;
                    layer.get_ref()
                }
                None => break,
            },
            (v, _) => v,
        };
        match value {
            DeValue::Table(t) => table = t,
            _ => break,
        }
    }
    line_col(text, offset)
}

/// The key whose value holds the byte `offset` (`calibration.speed_max`,
/// `calibration.data[1].speeds[0]`), to name the field of a TOML error that points at a value
/// and names none ("invalid type: string \"fast\", expected f64": issue 52); `None` when no
/// value holds it (an unknown or missing key, whose message names it).
pub(crate) fn key_at(text: &str, offset: usize) -> Option<String> {
    let doc = toml::de::DeTable::parse(text).ok()?;
    key_in(doc.get_ref(), offset)
}

fn key_in(table: &toml::de::DeTable, offset: usize) -> Option<String> {
    table.iter().find_map(|(key, value)| {
        value_path(value, offset).map(|rest| format!("{}{rest}", key.get_ref()))
    })
}

/// The path below `value` to the scalar holding `offset` ("" for `value` itself).
fn value_path(value: &toml::Spanned<toml::de::DeValue>, offset: usize) -> Option<String> {
    use toml::de::DeValue;
    match value.get_ref() {
        DeValue::Table(t) => key_in(t, offset).map(|p| format!(".{p}")),
        DeValue::Array(items) => items
            .iter()
            .enumerate()
            .find_map(|(i, item)| value_path(item, offset).map(|rest| format!("[{i}]{rest}"))),
        _ => value.span().contains(&offset).then(String::new),
    }
}
