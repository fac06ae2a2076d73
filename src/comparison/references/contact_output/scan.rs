//! The scan of CONTACT's printed output: its `Case n` lines, and in each case the blocks of
//! labels over one line of as many numbers that carry the totals (user guide, Section 6.1: the
//! output of module 3; m_soutpt.f90 prints them). Values as printed, CONTACT's signs.

use super::printed::Printed;
use super::ContactOutputError;

/// The blocks of printed values a case's totals are read from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BlockKind {
    /// `FN FX FY MZ ELAST.EN. FRIC.WORK|FRIC.POWER`.
    Totals,
    /// `FN/G FX/FSTAT/FN FY/FSTAT/FN APPROACH PMAX`, the x and y places taken by `FX/FN`,
    /// `CREEP X`, `SHIFT X` (and y) where those are printed instead.
    Ratios,
    /// `DT VELOC …` or `CHI DQ VELOC …`, then `CKSI CETA CPHI` or the prescribed forces.
    Kinematics,
    /// `FSTAT FKIN`, or the parameters of another friction law (`FKIN FEXP1 …`) or of friction
    /// per row (`IY FSTAT FKIN`: its first row only, the block is not Coulomb's).
    Friction,
    /// `NPOT NCON NADH NSLIP [NPLAST] INORM ITANG`.
    Statistics,
}

impl BlockKind {
    /// The block a line of labels heads, if it is one the totals are read from.
    fn of(labels: &[String]) -> Option<BlockKind> {
        let has = |l: &str| labels.iter().any(|x| x == l);
        let starts = |ls: &[&str]| labels.len() >= ls.len() && labels.iter().zip(ls).all(|(a, b)| a == b);
        if starts(&["FN", "FX", "FY", "MZ"]) {
            Some(BlockKind::Totals)
        } else if starts(&["FN/G"]) {
            Some(BlockKind::Ratios)
        } else if has("VELOC") && (starts(&["DT"]) || starts(&["CHI", "DQ"])) {
            Some(BlockKind::Kinematics)
        } else if has("FKIN") {
            Some(BlockKind::Friction)
        } else if starts(&["NPOT", "NCON", "NADH", "NSLIP"]) {
            Some(BlockKind::Statistics)
        } else {
            None
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            BlockKind::Totals => "TOTAL FORCES (FN FX FY MZ …)",
            BlockKind::Ratios => "totals' second line (FN/G … APPROACH PMAX)",
            BlockKind::Kinematics => "KINEMATIC CONSTANTS",
            BlockKind::Friction => "FRICTION LAW PARAMETERS",
            BlockKind::Statistics => "CONTACT STATISTICS",
        }
    }
}

/// One block: its labels with their printed values, and the line of the values (1-based).
#[derive(Debug, Clone)]
pub struct Block {
    pub kind: BlockKind,
    pub line: usize,
    pub values: Vec<(String, Printed)>,
}

impl Block {
    /// The value under `label`.
    pub fn get(&self, label: &str) -> Option<Printed> {
        self.values.iter().find(|(l, _)| l == label).map(|&(_, v)| v)
    }
}

/// One `Case n` of the file as scanned.
#[derive(Debug, Clone)]
pub struct ScannedCase {
    pub case: u32,
    /// The line of its `Case n` (1-based).
    pub line: usize,
    /// A wheel–rail case of module 1 (its markers: `WHEEL-RAIL CONTACT`, `DATA FOR CONTACT
    /// PATCH`, the control line `CPBTNFS.`); its blocks are not read.
    pub module1: bool,
    pub blocks: Vec<Block>,
}

impl ScannedCase {
    /// The case's last block of `kind`.
    pub fn block(&self, kind: BlockKind) -> Option<&Block> {
        self.blocks.iter().rev().find(|b| b.kind == kind)
    }
}

/// The case number of a `Case n` line (`Case 12`, `Case 3, result element 1`, `Case 2 for w/r
/// contact on result element 1`), or None.
fn case_number(line: &str) -> Option<u32> {
    let mut words = line.split_whitespace();
    (words.next()? == "Case").then_some(())?;
    words.next()?.trim_end_matches(',').parse().ok()
}

/// A module-1 (wheel–rail) case announces itself with one of these before its totals.
fn is_module1_marker(line: &str) -> bool {
    let t = line.trim_start();
    t.starts_with("CPBTNFS.")
        || t.starts_with("WHEEL-RAIL CONTACT")
        || t.starts_with("WHEEL-ROLLER CONTACT")
        || t.contains("DATA FOR CONTACT PATCH")
}

/// The labels of a line that holds no number, two-word labels joined (`SHIFT X`, `CREEP Y`).
pub(super) fn labels(line: &str) -> Option<Vec<String>> {
    let words: Vec<&str> = line.split_whitespace().collect();
    if words.is_empty() || words.iter().any(|w| Printed::parse(w).is_some()) {
        return None;
    }
    let mut out: Vec<String> = Vec::with_capacity(words.len());
    let mut k = 0;
    while k < words.len() {
        let pair = matches!(words[k], "SHIFT" | "CREEP") && matches!(words.get(k + 1), Some(&"X") | Some(&"Y"));
        if pair {
            out.push(format!("{} {}", words[k], words[k + 1]));
            k += 2;
        } else {
            out.push(words[k].to_string());
            k += 1;
        }
    }
    Some(out)
}

/// The values line under a block's labels: as many printed numbers as labels.
fn values(kind: BlockKind, labels: Vec<String>, text: Option<&str>, line: usize) -> Result<Block, ContactOutputError> {
    let text = text.unwrap_or("");
    let numbers: Option<Vec<Printed>> = text.split_whitespace().map(Printed::parse).collect();
    match numbers {
        Some(ns) if ns.len() == labels.len() => Ok(Block { kind, line, values: labels.into_iter().zip(ns).collect() }),
        _ => Err(ContactOutputError::Values {
            line,
            block: kind.name(),
            labels: labels.join(" "),
            got: crate::error::excerpt(text.trim()),
        }),
    }
}

/// Every `Case n` of `text` with its blocks, in the order printed.
pub fn scan(text: &str) -> Result<Vec<ScannedCase>, ContactOutputError> {
    let lines: Vec<&str> = text.lines().collect();
    let mut cases: Vec<ScannedCase> = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        if let Some(case) = case_number(line) {
            cases.push(ScannedCase { case, line: i + 1, module1: false, blocks: Vec::new() });
            continue;
        }
        let Some(current) = cases.last_mut() else { continue };
        if current.module1 {
            continue;
        }
        if is_module1_marker(line) {
            current.module1 = true;
            continue;
        }
        let Some(labels) = labels(line) else { continue };
        if let Some(kind) = BlockKind::of(&labels) {
            current.blocks.push(values(kind, labels, lines.get(i + 1).copied(), i + 2)?);
        }
    }
    if cases.is_empty() {
        return Err(ContactOutputError::NoCase);
    }
    Ok(cases)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn case_lines_of_every_form() {
        assert_eq!(case_number(" Case     2"), Some(2));
        assert_eq!(case_number(" Case   117"), Some(117));
        assert_eq!(case_number(" Case     3, result element   1"), Some(3));
        assert_eq!(case_number(" Case 2 for w/r contact on result element 1"), Some(2));
        assert_eq!(case_number(" Cases 1 - 2: Bentall"), None);
        assert_eq!(case_number(" Case"), None);
    }

    #[test]
    fn two_word_labels_are_one() {
        let l = labels("     FN/G       SHIFT X      SHIFT Y     APPROACH     PMAX    ").unwrap();
        assert_eq!(l, ["FN/G", "SHIFT X", "SHIFT Y", "APPROACH", "PMAX"]);
        assert_eq!(labels("     9.195      -3.218"), None);
        assert_eq!(BlockKind::of(&l), Some(BlockKind::Ratios));
    }

    #[test]
    fn a_block_with_a_value_missing_names_its_line() {
        let text =
            " Case     1\n     FN          FX          FY          MZ         ELAST.EN.   FRIC.WORK\n   9.195  0.0\n";
        let e = scan(text).unwrap_err();
        assert!(matches!(e, ContactOutputError::Values { line: 3, .. }), "{e:?}");
        assert!(e.to_string().contains("line 3"), "{e}");
    }
}
