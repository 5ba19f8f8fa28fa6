//! What the subcommands know of the vehicle they run besides its type:
//! its name, its powertrain, the real vehicle's published figures.

use trackgen::mobility::Published;
use trackgen::vehicle::Powertrain;

/// A vehicle as the application offers it.
pub struct Offered {
    /// The name `--vehicle` takes and the output folders use.
    pub name: String,
    /// The powertrain `run --engine` and the mobility events drive
    /// through, if any.
    pub powertrain: Option<Powertrain>,
    /// The real vehicle's published figures.
    pub published: Vec<Published>,
}

impl Offered {
    /// Its name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Its powertrain, or why it has none.
    pub fn engine(&self) -> Result<Powertrain, String> {
        self.powertrain.clone().ok_or_else(|| {
            format!(
                "the vehicle `{}` has no powertrain: declare one (`powertrain {{ … }}`) or give \
                 one with `Entry::powertrain`",
                self.name
            )
        })
    }

    /// Its published figures.
    pub fn figures(&self) -> &[Published] {
        &self.published
    }
}
