//! Nothing: the crate exists for its test, `tests/ui.rs`, which compiles
//! each bad declaration of `cases/` and compares its errors.
