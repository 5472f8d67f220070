//! Writing to the terminal without panicking. `println!` and `eprintln!` panic when their
//! stream is closed (`walls-sim run 2>&1 | head -1`); the tools print through
//! [`outln!`](crate::outln!) and [`errln!`](crate::errln!) instead (clippy's
//! `print_stdout` and `print_stderr` are denied in this crate):
//!
//! * standard output closed by its reader (a broken pipe) ends the process quietly with
//!   status 0, as `head` expects: nobody is left to read the rest;
//! * a failed write to standard error is dropped: the warning is lost, the command goes on
//!   and still writes its results.
//!
//! What the tools print is of two kinds, and this is where the difference is kept:
//!
//! * **human output**: messages, warnings, summaries, explanations, advice, diffs, clap's
//!   errors: [`outln!`](crate::outln!), [`out!`](crate::out!) and
//!   [`errln!`](crate::errln!) show every hazard of the text (a control character, a
//!   bidirectional override: [`walls_diagnostics::terminal`]) as its escape (`\x1b`),
//!   wherever the text came from (a file name, a `.par` value, a mesh's name).
//!   Diagnostics are drawn by `walls_diagnostics::render::human`, which escapes what it
//!   quotes and writes only its own colours, and diffs are escaped where they are made;
//! * **data**: formatted walls text, the walls file `walls-mesh` writes, JSON, SARIF,
//!   annotations, pictures and files: the bytes as they are, through [`out_data`] or the
//!   commands' own writers (the JSON and annotation renderers escape in their own way).
//!
//! [`color_stderr`] and [`color_stdout`] decide whether to colour a stream: on a terminal, or anywhere
//! when `CLICOLOR_FORCE` is set to anything but `0` (<https://bixense.com/clicolors/>, as
//! clap's own messages do); never when `NO_COLOR` is set to a non-empty value
//! (<https://no-color.org>), which wins.

use std::borrow::Cow;
use std::fmt::Arguments;
use std::io::{ErrorKind, IsTerminal, Write};
use walls_diagnostics::terminal;

/// Writes human text to standard output, its hazards escaped; see the module
/// documentation for what a closed stream does.
pub fn out(args: Arguments<'_>) {
    let text = escaped(args);
    let mut stdout = std::io::stdout().lock();
    if let Err(e) = stdout
        .write_all(text.as_bytes())
        .and_then(|()| stdout.flush())
    {
        out_failed(&e);
    }
}

/// Lets `write` write data to standard output, as it is, through a buffer, as it produces
/// its text (a large report is never held whole), then flushes it; a failed write ends
/// the process as in [`out`].
pub fn out_data(write: impl FnOnce(&mut dyn Write) -> std::io::Result<()>) {
    let mut stdout = std::io::BufWriter::new(std::io::stdout().lock());
    if let Err(e) = write(&mut stdout).and_then(|()| stdout.flush()) {
        out_failed(&e);
    }
}

/// Ends the process after a failed write to standard output: quietly with status 0 when
/// its reader has gone, else with status 2 and the error on standard error.
fn out_failed(e: &std::io::Error) -> ! {
    if e.kind() == ErrorKind::BrokenPipe {
        std::process::exit(0);
    }
    // Any other failure of standard output (a full disk behind a redirect) is for the
    // user to see; standard error may still be open.
    let _ = writeln!(
        std::io::stderr(),
        "error: cannot write to standard output: {e}"
    );
    std::process::exit(2);
}

/// Writes human text to standard error, its hazards escaped, dropping it if it cannot be
/// written; kept instead while [`capturing`] runs.
pub fn err(args: Arguments<'_>) {
    let text = escaped(args);
    if !kept(&text) {
        let _ = std::io::stderr().lock().write_all(text.as_bytes());
    }
}

/// Lets `write` write its text (a drawn diagnostic, coloured only where
/// [`color_stderr`] says) to standard error as it is, dropping what cannot be written;
/// kept instead while [`capturing`] runs.
pub fn err_data(write: impl FnOnce(&mut dyn Write) -> std::io::Result<()>) {
    if CAPTURED.with(|c| c.borrow().is_some()) {
        let mut text = Vec::new();
        let _ = write(&mut text);
        kept(&String::from_utf8_lossy(&text));
        return;
    }
    let mut stderr = std::io::BufWriter::new(std::io::stderr().lock());
    let _ = write(&mut stderr).and_then(|()| stderr.flush());
}

thread_local! {
    /// What this thread's commands wrote to standard error while [`capturing`] ran.
    static CAPTURED: std::cell::RefCell<Option<String>> = const { std::cell::RefCell::new(None) };
}

/// Runs `f`, keeping what it writes to standard error on this thread ([`err`],
/// [`err_data`], uncoloured) rather than writing it, and returns it with `f`'s value:
/// for a library caller that hands the messages on its own way (the Python package, as
/// warnings a notebook shows under its cell).
pub fn capturing<T>(f: impl FnOnce() -> T) -> (T, String) {
    /// Puts back what was kept before when dropped, even if `f` panics.
    struct Restore(Option<String>);
    impl Drop for Restore {
        fn drop(&mut self) {
            let before = self.0.take();
            CAPTURED.with(|c| *c.borrow_mut() = before);
        }
    }
    let _restore = Restore(CAPTURED.with(|c| c.replace(Some(String::new()))));
    let value = f();
    let text = CAPTURED.with(|c| c.borrow_mut().take()).unwrap_or_default();
    (value, text)
}

/// Keeps `text` if [`capturing`] runs on this thread; whether it did.
fn kept(text: &str) -> bool {
    CAPTURED.with(|c| match c.borrow_mut().as_mut() {
        Some(kept) => {
            kept.push_str(text);
            true
        }
        None => false,
    })
}

/// The text of `args` with every hazard shown as its escape: what [`out`] writes, for a
/// command that writes its human text through its own writer.
pub fn escaped(args: Arguments<'_>) -> String {
    let text = match args.as_str() {
        Some(text) => text.to_string(),
        None => args.to_string(),
    };
    match terminal::escape(&text) {
        Cow::Borrowed(_) => text,
        Cow::Owned(escaped) => escaped,
    }
}

/// Whether to colour standard error, where the tools write diagnostics: on a terminal
/// or with `CLICOLOR_FORCE` (not `0`), unless `NO_COLOR` is set to a non-empty value,
/// and never while [`capturing`] keeps it.
pub fn color_stderr() -> bool {
    !CAPTURED.with(|c| c.borrow().is_some())
        && color_with(
            std::io::stderr().is_terminal(),
            std::env::var_os("NO_COLOR").as_deref(),
            std::env::var_os("CLICOLOR_FORCE").as_deref(),
        )
}

/// Whether to colour standard output, where `walls-lint` writes its findings: as
/// [`color_stderr`], for standard output.
pub fn color_stdout() -> bool {
    color_with(
        std::io::stdout().is_terminal(),
        std::env::var_os("NO_COLOR").as_deref(),
        std::env::var_os("CLICOLOR_FORCE").as_deref(),
    )
}

/// Whether to colour a stream that is (or is not) a terminal, given the values of
/// `NO_COLOR` and `CLICOLOR_FORCE`.
fn color_with(
    is_terminal: bool,
    no_color: Option<&std::ffi::OsStr>,
    force: Option<&std::ffi::OsStr>,
) -> bool {
    let forced = force.is_some_and(|v| !v.is_empty() && v != std::ffi::OsStr::new("0"));
    (is_terminal || forced) && no_color.is_none_or(|v| v.is_empty())
}

/// `println!` for human text, which never panics and escapes hazards: see [`out`].
#[macro_export]
macro_rules! outln {
    () => { $crate::console::out(format_args!("\n")) };
    ($($arg:tt)*) => { $crate::console::out(format_args!("{}\n", format_args!($($arg)*))) };
}

/// `print!` for human text, which never panics and escapes hazards: see [`out`].
#[macro_export]
macro_rules! out {
    ($($arg:tt)*) => { $crate::console::out(format_args!($($arg)*)) };
}

/// `eprintln!` for human text, which never panics and escapes hazards: see [`err`].
#[macro_export]
macro_rules! errln {
    ($($arg:tt)*) => { $crate::console::err(format_args!("{}\n", format_args!($($arg)*))) };
}

#[cfg(test)]
mod tests {
    use super::{color_with, escaped};
    use std::ffi::OsStr;

    #[test]
    fn what_is_captured_is_kept_uncoloured_and_put_back_after_a_panic() {
        let (value, said) = super::capturing(|| {
            crate::errln!("walls-sim: warning: a\x1b.par: one");
            super::err_data(|w| w.write_all(b"drawn\n"));
            let (_, inner) = super::capturing(|| crate::errln!("inner"));
            assert_eq!(inner, "inner\n");
            assert!(!super::color_stderr());
            7
        });
        assert_eq!(value, 7);
        assert_eq!(said, "walls-sim: warning: a\\x1b.par: one\ndrawn\n");
        let caught = std::panic::catch_unwind(|| super::capturing(|| panic!("in f")));
        assert!(caught.is_err());
        assert!(!super::kept("not kept: nothing captures now"));
    }

    #[test]
    fn human_text_is_escaped_whatever_its_arguments() {
        let name = "a\x1b]52;c;aGk=\x07.walls";
        assert_eq!(
            escaped(format_args!("cannot read {name}: \u{202e}\r\n")),
            "cannot read a\\x1b]52;c;aGk=\\x07.walls: \\u{202e}\r\n"
        );
        assert_eq!(escaped(format_args!("plain\tline\n")), "plain\tline\n");
    }

    #[test]
    fn only_a_non_empty_no_color_turns_colour_off() {
        assert!(color_with(true, None, None));
        assert!(
            color_with(true, Some(OsStr::new("")), None),
            "NO_COLOR= (empty) keeps colour"
        );
        assert!(!color_with(true, Some(OsStr::new("1")), None));
        assert!(!color_with(false, None, None), "no colour off a terminal");
    }

    #[test]
    fn clicolor_force_colours_off_a_terminal_unless_no_color() {
        let (one, zero, empty) = (OsStr::new("1"), OsStr::new("0"), OsStr::new(""));
        assert!(color_with(false, None, Some(one)));
        assert!(!color_with(false, None, Some(zero)));
        assert!(!color_with(false, None, Some(empty)));
        assert!(!color_with(false, Some(one), Some(one)), "NO_COLOR wins");
    }
}
