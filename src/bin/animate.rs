//! `animate`: the frames of an animation manifest (`whitted_cli::animate`).

fn main() -> std::process::ExitCode {
    whitted_cli::animate::main()
}
