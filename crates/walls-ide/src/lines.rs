//! Where each line of a text starts, as editors count lines: a line ends at `\n`,
//! `\r\n` or a lone `\r`.

/// The start offset of every line of a text.
#[derive(Debug, Clone)]
pub struct Lines {
    starts: Vec<usize>,
}

impl Lines {
    /// Indexes `text`.
    pub fn new(text: &str) -> Self {
        let b = text.as_bytes();
        let mut starts = vec![0];
        for (i, &c) in b.iter().enumerate() {
            let ends = c == b'\n' || (c == b'\r' && b.get(i + 1) != Some(&b'\n'));
            if ends {
                starts.push(i + 1);
            }
        }
        Lines { starts }
    }

    /// The 0-based line holding byte `offset` (offsets past the end are on the last).
    pub fn line_of(&self, offset: usize) -> usize {
        self.starts.partition_point(|&s| s <= offset) - 1
    }

    /// Where 0-based `line` starts, if the text has that line.
    pub fn line_start(&self, line: usize) -> Option<usize> {
        self.starts.get(line).copied()
    }
}

#[cfg(test)]
mod tests {
    use super::Lines;

    #[test]
    fn every_line_ending_counts() {
        let lines = Lines::new("a\rb\r\nc\nd");
        assert_eq!(
            (0..4).map(|l| lines.line_start(l)).collect::<Vec<_>>(),
            [Some(0), Some(2), Some(5), Some(7)]
        );
        assert_eq!(lines.line_start(4), None);
        assert_eq!(lines.line_of(3), 1);
        assert_eq!(lines.line_of(99), 3);
    }
}
