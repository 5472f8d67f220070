//! Compiles the parser that `tree-sitter generate` wrote to `src/`.

fn main() {
    let src = std::path::Path::new("src");
    cc::Build::new()
        .std("c11")
        .include(src)
        .file(src.join("parser.c"))
        .warnings(false)
        .compile("tree-sitter-walls");
    println!("cargo:rerun-if-changed=src/parser.c");
}
