//! Typed records: a struct of recorded quantities whose column names are
//! its field names, so names and values cannot drift apart.

/// Declares a record: a struct of `f64` fields (each documented with its
/// unit), its `COLUMNS` (the field names, in order) and `extend_row`
/// (the values in that order).
macro_rules! record {
    (
        $(#[$meta:meta])*
        $vis:vis struct $name:ident {
            $( $(#[$field_meta:meta])* $field:ident ),* $(,)?
        }
    ) => {
        $(#[$meta])*
        #[derive(Debug, Clone, Copy, Default, PartialEq)]
        $vis struct $name {
            $( $(#[$field_meta])* pub $field: f64, )*
        }

        impl $name {
            /// The column names, in order: the fields' names.
            pub const COLUMNS: &'static [&'static str] = &[$(stringify!($field)),*];

            /// Every value NaN: not observed. A lean observation fills in
            /// the fields that were asked for.
            pub const fn unobserved() -> Self {
                $name { $( $field: f64::NAN, )* }
            }

            /// Appends the values to `row`, in the order of
            /// [`COLUMNS`](Self::COLUMNS).
            #[inline]
            pub fn extend_row(&self, row: &mut Vec<f64>) {
                row.extend([$(self.$field),*]);
            }
        }
    };
}

pub(crate) use record;
