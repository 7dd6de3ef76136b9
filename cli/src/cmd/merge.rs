//! `aes-sim merge`: shards of any study (Monte Carlo, rare events, the operability polar, fuel per
//! mile) into the study's summary, as the study's own command prints it.

use crate::common::{Failure, OutFile};

// The command line of `aes-sim merge`.
#[derive(clap::Args)]
pub struct Args {
    /// Shard files (`--partial` of `aes-sim mc`, `rare`, `operability` or `fuel-per-mile`), all of
    /// one study.
    #[arg(required_unless_present = "files_from")]
    files: Vec<String>,
    /// Also merge the shard files listed in this file, one path a line (`-`: standard input;
    /// for more shards than a command line holds).
    #[arg(long = "files-from", value_name = "LIST")]
    files_from: Option<String>,
    /// Also write the merged shard to this file.
    #[arg(long)]
    partial: Option<String>,
}

pub fn run(Args { files, files_from, partial }: Args) -> Result<(), Failure> {
    // The output may not be one of the inputs (the shard would be lost): the named shards, the
    // list, and (as they are read) every shard the list names. Written only at the end.
    let inputs: Vec<&str> = files.iter().map(String::as_str).chain(files_from.as_deref()).collect();
    let partial = partial.map(|path| OutFile::check(&path, "--partial", &inputs)).transpose()?;
    // The listed names are read line by line as they are merged (never all at once), each line
    // and the whole list bounded.
    let listed: Box<dyn Iterator<Item = std::io::Result<String>>> = match files_from.as_deref() {
        None => Box::new(std::iter::empty()),
        Some("-") => Box::new(ListLines::new(std::io::stdin().lock(), "standard input".into())),
        Some(list) => {
            let name = format!("'{}'", crate::common::shorten(list));
            let f = std::fs::File::open(list).map_err(|e| format!("--files-from {name}: cannot read: {e}"))?;
            Box::new(ListLines::new(std::io::BufReader::new(f), name))
        }
    };
    let mut all = files.into_iter().map(Ok).chain(listed).filter(|f| !matches!(f, Ok(f) if f.trim().is_empty()));
    let first = match all.next() {
        None => return Err("no shards given".into()),
        Some(f) => f.map_err(|e| format!("--files-from: {e}"))?,
    };
    crate::study::merge_any(first, all, partial)
}

/// Longest line of a `--files-from` list, a shard file's name [bytes] (Linux's PATH_MAX), and
/// longest list [bytes] (about 500,000 names of 128 bytes).
pub const MAX_LIST_LINE: u64 = 4096;
pub const MAX_LIST_BYTES: u64 = 64 << 20;

/// The lines of a `--files-from` list, each read only up to [`MAX_LIST_LINE`] bytes and all
/// together up to [`MAX_LIST_BYTES`]: an endless line (`/dev/zero`) or list is refused after
/// reading a little past the limit, never read whole. The first error ends the list.
struct ListLines<R> {
    reader: R,
    /// The list as messages name it.
    name: String,
    line: u64,
    read: u64,
    ended: bool,
}

impl<R: std::io::BufRead> ListLines<R> {
    fn new(reader: R, name: String) -> ListLines<R> {
        ListLines { reader, name, line: 0, read: 0, ended: false }
    }

    fn next_line(&mut self) -> std::io::Result<Option<String>> {
        use std::io::{BufRead, Read};
        let mut buf = Vec::new();
        let n = (&mut self.reader).take(MAX_LIST_LINE + 1).read_until(b'\n', &mut buf)? as u64;
        if n == 0 {
            return Ok(None);
        }
        self.line += 1;
        self.read += n;
        let refuse = |what: String| Err(std::io::Error::new(std::io::ErrorKind::InvalidData, what));
        if self.read > MAX_LIST_BYTES {
            return refuse(format!(
                "{} is longer than {MAX_LIST_BYTES} bytes (at line {}), the limit for a list of shard files",
                self.name, self.line
            ));
        }
        if buf.last() == Some(&b'\n') {
            buf.pop();
        } else if n > MAX_LIST_LINE {
            return refuse(format!(
                "line {} of {} is longer than {MAX_LIST_LINE} bytes, the limit for a shard file's name",
                self.line, self.name
            ));
        }
        if buf.last() == Some(&b'\r') {
            buf.pop();
        }
        match String::from_utf8(buf) {
            Ok(s) => Ok(Some(s)),
            Err(e) => refuse(format!(
                "line {} of {} is not UTF-8 text (byte {})",
                self.line,
                self.name,
                e.utf8_error().valid_up_to() + 1
            )),
        }
    }
}

impl<R: std::io::BufRead> Iterator for ListLines<R> {
    type Item = std::io::Result<String>;
    fn next(&mut self) -> Option<std::io::Result<String>> {
        if self.ended {
            return None;
        }
        let r = self.next_line().transpose();
        self.ended = !matches!(r, Some(Ok(_)));
        r
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lines(text: &[u8]) -> Vec<Result<String, String>> {
        ListLines::new(text, "'list'".into()).map(|r| r.map_err(|e| e.to_string())).collect()
    }

    /// Lines up to the limit pass (with or without a last newline, CRLF too); one byte more is
    /// refused and ends the list; a list of endless zeros is refused after reading one line's
    /// limit and a byte.
    #[test]
    fn list_lines_are_bounded() {
        let ok = |s: &str| Ok(s.to_string());
        assert_eq!(lines(b"a.json\r\nb.json\n\nc.json"), [ok("a.json"), ok("b.json"), ok(""), ok("c.json")]);
        let longest = "x".repeat(MAX_LIST_LINE as usize);
        assert_eq!(lines(format!("{longest}\n{longest}").as_bytes()), [ok(&longest), ok(&longest)]);
        let long = format!("a.json\n{longest}y\nb.json\n");
        assert_eq!(
            lines(long.as_bytes()),
            [ok("a.json"), Err("line 2 of 'list' is longer than 4096 bytes, the limit for a shard file's name".into())]
        );
        let mut zeros = std::io::BufReader::new(std::io::Read::take(std::io::repeat(0), 1 << 40));
        let mut list = ListLines::new(&mut zeros, "'/dev/zero'".into());
        assert!(list.next().is_some_and(|r| r.is_err()));
        assert!(list.next().is_none());
        assert_eq!(lines(b"a\xff.json\n"), [Err("line 1 of 'list' is not UTF-8 text (byte 2)".into())]);
    }

    /// The whole list is bounded too: 64 MB of names of 1,000 bytes is refused at the limit.
    #[test]
    fn the_list_is_bounded() {
        struct Names;
        impl std::io::Read for Names {
            fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
                for (i, b) in buf.iter_mut().enumerate() {
                    *b = if i % 1000 == 999 { b'\n' } else { b'x' };
                }
                Ok(buf.len())
            }
        }
        let list = ListLines::new(std::io::BufReader::new(Names), "standard input".into());
        let (mut names, mut last) = (0, None);
        for r in list {
            match r {
                Ok(_) => names += 1,
                Err(e) => last = Some(e.to_string()),
            }
        }
        let e = last.unwrap();
        assert!(e.starts_with("standard input is longer than 67108864 bytes (at line "), "{e}");
        assert!(e.ends_with("), the limit for a list of shard files"), "{e}");
        assert!(names > 60_000, "{names}");
    }
}
