//! Bad declarations are compile errors at the offending token, all at once
//! (trybuild; the expected messages are the `.stderr` files beside each
//! case in cases/, stable because the toolchain is pinned). A crate of
//! its own, so that trybuild checks the facade with nothing but what a
//! user's crate would have: trybuild builds every dev-dependency of the
//! package it runs in.

#[test]
fn bad_declarations_are_compile_errors() {
    let t = trybuild::TestCases::new();
    t.compile_fail("cases/*.rs");
}
