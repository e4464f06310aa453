//! The `nrgdb` command line: a thin layer over the library (see `cli/`).

mod cli;

use std::io::{self, Write};
use std::process::ExitCode;

use clap::Parser;

/// Standard output for the subcommands: a reader that went away
/// (`nrgdb log | head`) ends the program quietly with success, wherever
/// the write happened, so no subcommand has to know about broken pipes.
struct Stdout<W: Write>(W);

impl<W: Write> Stdout<W> {
    fn check<T>(result: io::Result<T>) -> io::Result<T> {
        if let Err(e) = &result
            && e.kind() == io::ErrorKind::BrokenPipe
        {
            std::process::exit(0);
        }
        result
    }
}

impl<W: Write> Write for Stdout<W> {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        Self::check(self.0.write(buf))
    }
    fn flush(&mut self) -> io::Result<()> {
        Self::check(self.0.flush())
    }
}

fn main() -> ExitCode {
    // Errors print as plain lines that never wrap, so scripts can grep them.
    let _ = miette::set_hook(Box::new(|_| {
        Box::new(miette::MietteHandlerOpts::new().wrap_lines(false).build())
    }));
    let args = cli::Cli::parse();
    cli::init_logging(args.verbose);
    let mut stdout = Stdout(io::stdout().lock());
    let code = match cli::run(args.command, &mut stdout) {
        Ok(code) => code,
        Err(report) => {
            eprintln!("{report:?}");
            ExitCode::from(2)
        }
    };
    let _ = stdout.flush();
    code
}
