//! The files of a run: opened before it starts (a folder that cannot be
//! written fails at once, not after the run), fed as it goes, pictures
//! drawn at the end from a bounded selection of rows.

use std::error::Error;
use std::fs::File;
use std::path::{Path, PathBuf};

use trackgen::simulate::{CsvSink, Results, RideSink, Select, Summary, Tee, Thinned};
use trackgen_arrow::ArrowSink;
use trackgen_draw::{animation, plots, vehicle};

use super::nearest::Nearest;
use trackgen::scene::{Ground, Scene};

/// The columns of `<vehicle>.csv`.
const MAIN_COLUMNS: [&str; 11] = [
    "x",
    "y",
    "pitch",
    "speed",
    "sprocket_torque",
    "sprocket_speed",
    "engine_load",
    "tension",
    "ground_normal",
    "seat_ax",
    "seat_az",
];

/// Rows kept in memory for the plots and the animation, evenly spaced:
/// a run shorter than 20 s at the 0.01 s output interval keeps every row;
/// longer ones every 2nd, 4th, … (≤ 2000 × ~90 numbers, 1.4 MB).
const PICTURE_ROWS: usize = 2000;
/// Frames of the animation: at most this many, 0.04 s apart or more.
const MAX_FRAMES: f64 = 1500.0;

pub struct Outputs {
    dir: PathBuf,
    /// The vehicle's name, in file names.
    name: String,
    /// Its title, in the animation.
    title: String,
    scene: Scene,
    /// What the run feeds: apart from the scene, so that they can be fed
    /// on another thread.
    pub recorders: Recorders,
}

/// The sinks of a run.
pub struct Recorders {
    all_csv: CsvSink<File>,
    all_arrow: ArrowSink<File>,
    main_csv: Select<CsvSink<File>>,
    /// First, last and extreme values of every column, for the report.
    pub summary: Summary,
    picture_columns: Vec<String>,
    thinned: Thinned,
    at_bump: Nearest,
    /// The ride at the seat, when the rows are close enough together.
    pub ride: Option<RideSink>,
}

impl Recorders {
    /// Everything a run feeds, as one sink.
    pub fn sink(&mut self) -> Tee<'_> {
        let pictures = Tee::new().and(&mut self.thinned).and(&mut self.at_bump);
        let all = Tee::new()
            .and(&mut self.all_csv)
            .and(&mut self.all_arrow)
            .and(&mut self.main_csv)
            .and(&mut self.summary)
            .and(Select::new(self.picture_columns.clone(), pictures));
        match &mut self.ride {
            Some(ride) => all.and(ride),
            None => all,
        }
    }
}

impl Outputs {
    /// Creates the folder and the data files for a run of the vehicle
    /// `name` (drawn by `scene`, titled `title`) recording `columns`; the
    /// picture is taken where the chassis centroid passes `focus` (m).
    pub fn create(
        dir: &Path,
        (name, title, scene): (&str, String, Scene),
        columns: &[String],
        focus: f64,
    ) -> Result<Self, Box<dyn Error>> {
        std::fs::create_dir_all(dir)
            .map_err(|e| format!("cannot create the output folder {}: {e}", dir.display()))?;
        let mut picture_columns = scene
            .columns(columns)
            .ok_or("the system records no track and chassis coordinates")?;
        picture_columns.extend(plots::columns());
        picture_columns.push("x".to_string());
        Ok(Outputs {
            dir: dir.to_path_buf(),
            name: name.to_string(),
            title,
            scene,
            recorders: Recorders {
                all_csv: CsvSink::create(dir.join("all.csv"))?,
                all_arrow: ArrowSink::create(dir.join("all.arrow"))?,
                main_csv: Select::new(
                    MAIN_COLUMNS,
                    CsvSink::create(dir.join(format!("{name}.csv")))?,
                ),
                summary: Summary::new(),
                picture_columns,
                thinned: Thinned::new(PICTURE_ROWS),
                at_bump: Nearest::new("x", focus),
                ride: None,
            },
        })
    }

    /// Draws the plots, the frame at the bump and the animation (when the
    /// run has at least two rows); returns the names of every file
    /// written.
    pub fn draw(&self, ground: &Ground) -> Result<Vec<String>, Box<dyn Error>> {
        let mut written = self.data_files();
        let kept = self.recorders.thinned.results();
        if kept.len() < 2 {
            return Ok(written);
        }
        // The plots on a second thread while this one draws the scene:
        // the two are independent, and the machine has the cores.
        let plot = format!("{}.svg", self.name);
        let plot_path = self.dir.join(&plot);
        let (plotted, scene) = std::thread::scope(|scope| {
            let plotting = scope.spawn(|| plots::draw(kept, &plot_path).map_err(|e| e.to_string()));
            let scene = self.draw_scene(kept, ground);
            let plotted = plotting
                .join()
                .unwrap_or_else(|panic| std::panic::resume_unwind(panic));
            (plotted, scene)
        });
        plotted?;
        written.push(plot);
        written.extend(scene?);
        Ok(written)
    }

    /// `frame.svg` (at the bump) and `animation.html` (the run), returning
    /// the names written.
    fn draw_scene(&self, kept: &Results, ground: &Ground) -> Result<Vec<String>, Box<dyn Error>> {
        let mut written = Vec::new();
        if let Some(frame) = self
            .scene
            .frames(self.recorders.at_bump.results(), 0.0)
            .first()
        {
            std::fs::write(self.dir.join("frame.svg"), vehicle::svg(frame, ground))?;
            written.push("frame.svg".to_string());
        }
        let span = kept.times().last().unwrap_or(&0.0) - kept.times()[0];
        let frames = self.scene.frames(kept, (span / MAX_FRAMES).max(0.04));
        std::fs::write(
            self.dir.join("animation.html"),
            animation::html(&frames, ground, &self.title),
        )?;
        written.push("animation.html".to_string());
        Ok(written)
    }

    /// The data files, written as the run goes.
    pub fn data_files(&self) -> Vec<String> {
        vec![
            format!("{}.csv", self.name),
            "all.csv".into(),
            "all.arrow".into(),
        ]
    }

    /// The output folder.
    pub fn dir(&self) -> &Path {
        &self.dir
    }
}
