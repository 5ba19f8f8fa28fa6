//! Bad declarations are compile errors at the offending token, all at once
//! (trybuild; the expected messages are the `.stderr` files beside each
//! case in tests/ui/, stable because the toolchain is pinned).

#[test]
fn bad_declarations_are_compile_errors() {
    let t = trybuild::TestCases::new();
    t.compile_fail("tests/ui/*.rs");
}
