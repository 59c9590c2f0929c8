//! A report as a list of blocks, rendered twice: as Markdown (`report.md`, charts linked from
//! `plots/`) and as one self-contained HTML page (`report.html`: inline CSS, charts inlined as
//! SVG, no script, no network). Text may hold `` `code` `` and `**bold**` spans.

use crate::svg::{esc, push_esc};
use anyhow::Context;
use std::fmt::Write as _;
use std::path::Path;

/// Column alignment.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Align {
    Left,
    Right,
}

/// One block of a report.
#[derive(Debug, Clone)]
pub enum Block {
    /// A heading of level 1-4.
    Heading(u8, String),
    Paragraph(String),
    List(Vec<String>),
    Table {
        header: Vec<String>,
        align: Vec<Align>,
        rows: Vec<Vec<String>>,
    },
    /// A chart: its file under the report's folder, the SVG text, a caption.
    Figure {
        file: String,
        svg: String,
        caption: String,
    },
    /// A link list: (text, relative address, note).
    Links(Vec<(String, String, String)>),
}

/// A whole report.
#[derive(Debug, Clone, Default)]
pub struct Doc {
    pub title: String,
    pub blocks: Vec<Block>,
}

impl Doc {
    /// Appends a block.
    pub fn push(&mut self, b: Block) {
        self.blocks.push(b);
    }

    /// The report as Markdown.
    pub fn markdown(&self) -> String {
        let mut o = format!("# {}\n\n", self.title);
        for b in &self.blocks {
            match b {
                Block::Heading(level, t) => {
                    let _ = writeln!(o, "{} {t}\n", "#".repeat(*level as usize));
                }
                Block::Paragraph(t) => {
                    let _ = writeln!(o, "{t}\n");
                }
                Block::List(items) => {
                    for i in items {
                        let _ = writeln!(o, "- {i}");
                    }
                    o.push('\n');
                }
                Block::Table {
                    header,
                    align,
                    rows,
                } => {
                    let cell = |s: &str| s.replace('|', "\\|");
                    let _ = writeln!(
                        o,
                        "| {} |",
                        header
                            .iter()
                            .map(|h| cell(h))
                            .collect::<Vec<_>>()
                            .join(" | ")
                    );
                    let rule: Vec<&str> = (0..header.len())
                        .map(|k| match align.get(k) {
                            Some(Align::Right) => "---:",
                            _ => "---",
                        })
                        .collect();
                    let _ = writeln!(o, "|{}|", rule.join("|"));
                    for r in rows {
                        let _ = writeln!(
                            o,
                            "| {} |",
                            r.iter().map(|h| cell(h)).collect::<Vec<_>>().join(" | ")
                        );
                    }
                    o.push('\n');
                }
                Block::Figure { file, caption, .. } => {
                    let _ = writeln!(o, "![{caption}]({file})\n");
                }
                Block::Links(links) => {
                    for (text, href, note) in links {
                        let _ = writeln!(o, "- [{text}]({href}){}", note_suffix(note));
                    }
                    o.push('\n');
                }
            }
        }
        o
    }

    /// The report as one self-contained HTML page.
    pub fn html(&self) -> String {
        let mut o = String::with_capacity(64 * 1024);
        o.push_str("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n");
        o.push_str("<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n");
        let _ = writeln!(o, "<title>{}</title>", esc(&self.title));
        let _ = writeln!(o, "<style>{CSS}</style>\n</head>\n<body>");
        let _ = writeln!(o, "<h1>{}</h1>", esc(&self.title));
        for b in &self.blocks {
            match b {
                Block::Heading(level, t) => {
                    let _ = write!(o, "<h{level}>");
                    push_inline(&mut o, t);
                    let _ = writeln!(o, "</h{level}>");
                }
                Block::Paragraph(t) => {
                    o.push_str("<p>");
                    push_inline(&mut o, t);
                    o.push_str("</p>\n");
                }
                Block::List(items) => {
                    o.push_str("<ul>\n");
                    for i in items {
                        o.push_str("<li>");
                        push_inline(&mut o, i);
                        o.push_str("</li>\n");
                    }
                    o.push_str("</ul>\n");
                }
                Block::Table {
                    header,
                    align,
                    rows,
                } => {
                    o.push_str("<table>\n<thead><tr>");
                    for h in header {
                        o.push_str("<th>");
                        push_inline(&mut o, h);
                        o.push_str("</th>");
                    }
                    o.push_str("</tr></thead>\n<tbody>\n");
                    for r in rows {
                        o.push_str("<tr>");
                        for (k, cell) in r.iter().enumerate() {
                            o.push_str(match align.get(k) {
                                Some(Align::Right) => "<td class=\"num\">",
                                _ => "<td>",
                            });
                            push_inline(&mut o, cell);
                            o.push_str("</td>");
                        }
                        o.push_str("</tr>\n");
                    }
                    o.push_str("</tbody>\n</table>\n");
                }
                Block::Figure { file, svg, caption } => {
                    let _ = writeln!(
                        o,
                        "<figure>\n{}<figcaption>{} (<a href=\"{}\">SVG</a>)</figcaption>\n</figure>",
                        svg,
                        inline(caption),
                        esc(file)
                    );
                }
                Block::Links(links) => {
                    o.push_str("<ul>\n");
                    for (text, href, note) in links {
                        let _ = writeln!(
                            o,
                            "<li><a href=\"{}\">{}</a>{}</li>",
                            esc(href),
                            esc(text),
                            inline(&note_suffix(note))
                        );
                    }
                    o.push_str("</ul>\n");
                }
            }
        }
        o.push_str("</body>\n</html>\n");
        o
    }
}

fn note_suffix(note: &str) -> String {
    if note.is_empty() {
        String::new()
    } else {
        format!(": {note}")
    }
}

/// Escapes `text` and turns `` `code` `` and `**bold**` spans into HTML.
pub fn inline(text: &str) -> String {
    let mut o = String::with_capacity(text.len() + 16);
    push_inline(&mut o, text);
    o
}

/// Appends [`inline`] of `text` to `o`, without a string of its own (issue 37).
fn push_inline(o: &mut String, text: &str) {
    for (k, part) in text.split('`').enumerate() {
        if k % 2 == 1 {
            o.push_str("<code>");
            push_esc(o, part);
            o.push_str("</code>");
            continue;
        }
        // The pieces between `**`s, left to right (as `split("**")`, by bytes).
        let mut rest = part;
        for j in 0.. {
            let at = rest.as_bytes().windows(2).position(|w| w == b"**");
            let piece = at.map_or(rest, |k| &rest[..k]);
            if j % 2 == 1 {
                o.push_str("<strong>");
                push_esc(o, piece);
                o.push_str("</strong>");
            } else {
                push_esc(o, piece);
            }
            match at {
                Some(k) => rest = &rest[k + 2..],
                None => break,
            }
        }
    }
}

/// The page style: readable tables, charts scaled to the page width.
pub const CSS: &str = "body{font-family:sans-serif;max-width:1100px;margin:1em auto;padding:0 1em;color:#222;line-height:1.4}\
table{border-collapse:collapse;margin:.5em 0 1.2em;font-size:90%}\
th,td{border:1px solid #ccc;padding:.2em .5em;text-align:left}\
th{background:#f0f0f0}td.num{text-align:right;font-variant-numeric:tabular-nums}\
tbody tr:nth-child(even){background:#fafafa}\
code{font-size:95%;background:#f4f4f4;padding:0 .2em}\
figure{margin:1em 0}figure svg{max-width:100%;height:auto}figcaption{font-size:90%;color:#555}\
h2{border-bottom:1px solid #ddd;padding-bottom:.2em;margin-top:1.6em}";

/// A relative address: every byte outside `A-Z a-z 0-9 - _ . ~ /` percent-encoded.
pub fn href(path: &str) -> String {
    let mut o = String::with_capacity(path.len());
    for b in path.bytes() {
        if b.is_ascii_alphanumeric() || b"-_.~/".contains(&b) {
            o.push(b as char);
        } else {
            o.push_str(&format!("%{b:02X}"));
        }
    }
    o
}

/// Writes `report.md`, `report.html` and `plots/<name>.svg` into `dir`; an older `plots/`
/// folder is replaced.
pub(crate) fn write_report(
    dir: &Path,
    doc: &Doc,
    plots: &[(String, String)],
) -> anyhow::Result<()> {
    let plots_dir = dir.join("plots");
    if plots_dir.exists() {
        std::fs::remove_dir_all(&plots_dir)
            .with_context(|| format!("remove {}", plots_dir.display()))?;
    }
    if !plots.is_empty() {
        std::fs::create_dir_all(&plots_dir)
            .with_context(|| format!("create {}", plots_dir.display()))?;
    }
    for (name, svg) in plots {
        crate::files::write_file(&plots_dir.join(name), svg.as_bytes())?;
    }
    crate::files::write_file(&dir.join("report.md"), doc.markdown().as_bytes())?;
    crate::files::write_file(&dir.join("report.html"), doc.html().as_bytes())?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inline_spans_are_as_split_made_them() {
        // `inline` as it was: `split('`')`, then `split("**")`, each piece escaped.
        let by_split = |text: &str| {
            let mut o = String::new();
            for (k, part) in text.split('`').enumerate() {
                if k % 2 == 1 {
                    o.push_str(&format!("<code>{}</code>", esc(part)));
                } else {
                    for (j, p) in part.split("**").enumerate() {
                        if j % 2 == 1 {
                            o.push_str(&format!("<strong>{}</strong>", esc(p)));
                        } else {
                            o.push_str(&esc(p));
                        }
                    }
                }
            }
            o
        };
        for text in [
            "",
            "plain",
            "**bold**",
            "a **b** c `d` e",
            "***",
            "****",
            "a***b",
            "**a**b**",
            "`code **not bold**`",
            "`unclosed",
            "**unclosed",
            "Δ = (mechanism − reference) / |reference| × 100 %, to `slider_crank` & <x>",
            "*",
            "x*y**z",
        ] {
            assert_eq!(inline(text), by_split(text), "{text}");
        }
    }
}
