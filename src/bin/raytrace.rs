//! `raytrace`: one image from a Scene.txt or NFF file (`whitted_cli::raytrace`).

fn main() -> std::process::ExitCode {
    whitted_cli::raytrace::main()
}
