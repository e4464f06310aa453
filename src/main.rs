//! The `nrgdb` command line: a thin layer over the library (see `cli/`).

mod cli;

use std::process::ExitCode;

use clap::Parser;

fn main() -> ExitCode {
    // Errors print as plain lines that never wrap, so scripts can grep them.
    let _ = miette::set_hook(Box::new(|_| {
        Box::new(miette::MietteHandlerOpts::new().wrap_lines(false).build())
    }));
    let args = cli::Cli::parse();
    cli::init_logging(args.verbose);
    let stdout = std::io::stdout();
    match cli::run(args.command, &mut stdout.lock()) {
        Ok(code) => code,
        Err(report) => {
            if cli::is_broken_pipe(&report) {
                return ExitCode::SUCCESS;
            }
            eprintln!("{report:?}");
            ExitCode::from(2)
        }
    }
}
