//! The `arch-enum` binary: a thin shell over [`arch_enum::cli::run`].

#![forbid(unsafe_code)]

fn main() {
    let code = arch_enum::cli::run(
        std::env::args_os(),
        &mut std::io::stdout(),
        &mut std::io::stderr(),
    );
    std::process::exit(code);
}
