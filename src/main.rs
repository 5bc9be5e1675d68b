fn main() {
    let path = std::env::args().nth(1).unwrap_or_default();
    let src = std::fs::read_to_string(&path).unwrap_or_default();
    let mut sources = adair::diag::Sources::default();
    let id = sources.add(path.clone(), src.clone());
    let (ast, diags) = adair::syntax::parse_source(&src, id);
    print!("{}", adair::diag::render(&diags, &sources, false));
    println!("{:#?}", ast.map(|a| a.items.len()));
}
