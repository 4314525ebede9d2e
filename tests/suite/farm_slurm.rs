//! The render farm for real (SPEC §9, issue 11): a one-node Slurm cluster brought up on
//! this machine (`farm/ci/slurm-cluster.sh`: munged, slurmctld and slurmd from Debian's
//! `slurm-wlm` and `munge`, all state in a temporary folder, stopped by their pid files
//! whatever happens) runs the job files of `farm/slurm` (`farm/ci/slurm-scenario.sh`): an
//! array job `--array=1-3` of `animate --shard auto --resume`, task 2 cancelled while it
//! runs and rerun, and the dependent ffmpeg job. Then: every frame is byte-identical to a
//! single-process run, the rerun rendered only the frames the cancelled attempt had not,
//! ffprobe counts every frame in the video, and the folder is complete.
//!
//! Needs root, Slurm, munge and ffmpeg; `.ci/run` installs them. Elsewhere the test says
//! "skipped: …" and passes, except under CI, where their absence fails it.

use crate::skip;
use crate::support;

use std::path::Path;
use std::process::Command;
use support::*;

const FRAMES: u32 = 60;
const TASKS: u32 = 3;

/// Why the cluster cannot run here, if it cannot.
fn missing() -> Option<String> {
    let uid = Command::new("id").arg("-u").output().ok()?;
    if String::from_utf8_lossy(&uid.stdout).trim() != "0" {
        return Some("the Slurm test starts slurmctld and slurmd, which needs root".into());
    }
    let tools = [
        "munged",
        "slurmctld",
        "slurmd",
        "sbatch",
        "scontrol",
        "squeue",
        "scancel",
        "sinfo",
        "ffmpeg",
        "ffprobe",
    ];
    let absent: Vec<&str> = tools
        .into_iter()
        .filter(|t| {
            let probe = format!("command -v {t}");
            !Command::new("sh")
                .args(["-c", &probe])
                .output()
                .is_ok_and(|o| o.status.success())
        })
        .collect();
    (!absent.is_empty()).then(|| {
        format!(
            "not installed: {} (apt-get install -y slurm-wlm munge ffmpeg)",
            absent.join(", ")
        )
    })
}

/// 60 frames heavy enough (320×240, 2×2 samples) that a task of 20 runs for seconds, long
/// enough to be cancelled half-way.
fn manifest() -> String {
    format!(
        "scene = \"scene.txt\"\nframes = {FRAMES}\nfps = 25\n\n[camera]\npath = \"circle\"\n\
         center = [0.0, 1.0, 0.0]\nradius = 8.0\nheight = 3.0\n\n[output]\ndir = \"frames\"\n\
         name = \"frame_####\"\nformat = \"png\"\n\n[render]\nwidth = 320\nheight = 240\n\
         samples = 2\n"
    )
}

/// (width, height, frames) of the video's first stream, from ffprobe.
fn probe(video: &Path) -> (u32, u32, u32) {
    let out = Command::new("ffprobe")
        .args(["-v", "error", "-select_streams", "v:0", "-count_frames"])
        .args(["-show_entries", "stream=width,height,nb_read_frames"])
        .args(["-of", "csv=p=0"])
        .arg(video)
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    let n: Vec<u32> = text.trim().split(',').map(|f| f.parse().unwrap()).collect();
    (n[0], n[1], n[2])
}

/// (rendered, up to date) from each `animate: N frames rendered, M up to date in …` line
/// of a log.
fn summaries(log: &str) -> Vec<(u32, u32)> {
    log.lines()
        .filter_map(|l| l.strip_prefix("animate: "))
        .filter_map(|l| {
            let (rendered, rest) = l.split_once(" rendered, ")?;
            let rendered = rendered
                .trim_end_matches(" frames")
                .trim_end_matches(" frame");
            let (skipped, _) = rest.split_once(" up to date")?;
            Some((rendered.parse().ok()?, skipped.parse().ok()?))
        })
        .collect()
}

/// The frame counts of the TASKS shards `--shard auto --balance` makes of `manifest`.
fn balanced_sizes(manifest: &Path) -> Vec<u32> {
    use whitted_anim::frames::balance::{predicted_costs, split};
    let project = whitted_anim::Project::load(manifest).unwrap();
    let anim = whitted_anim::Animation::new(&project).unwrap();
    let frames: Vec<u32> = (0..FRAMES).collect();
    let costs = predicted_costs(&anim, &frames).unwrap();
    let b = split(&costs, TASKS);
    b.windows(2).map(|w| (w[1] - w[0]) as u32).collect()
}

#[test]
fn a_slurm_array_with_a_cancelled_task_renders_the_single_run() {
    if let Some(why) = missing() {
        skip::skip(&why);
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let work = dir.path();
    std::fs::write(work.join("scene.txt"), scene_with_eye([0.0, 3.0, 8.0])).unwrap();
    std::fs::write(work.join("anim.toml"), manifest()).unwrap();
    render_into(&work.join("anim.toml"), &work.join("single"), &[]);
    // render.sbatch balances the shards by predicted cost: the tasks' frame counts.
    let sizes = balanced_sizes(&work.join("anim.toml"));
    let first = sizes[0];
    let end = first + sizes[1];

    let farm = Path::new(env!("CARGO_MANIFEST_DIR")).join("farm/ci");
    let run = Command::new(farm.join("slurm-cluster.sh"))
        .arg(work.join("cluster"))
        .arg(farm.join("slurm-scenario.sh"))
        .arg(work)
        .args([FRAMES, TASKS, first, end].map(|n| n.to_string()))
        .env("ANIMATE", env!("CARGO_BIN_EXE_animate"))
        .output()
        .unwrap();
    let said = format!(
        "{}{}",
        String::from_utf8_lossy(&run.stdout),
        String::from_utf8_lossy(&run.stderr)
    );
    eprintln!("{said}");
    assert!(run.status.success(), "the Slurm scenario failed:\n{said}");

    let frames = files(&work.join("frames"));
    assert_eq!(frames.len(), FRAMES as usize);
    assert!(
        frames == files(&work.join("single")),
        "frames differ from a single run"
    );

    // Task 2's first attempt was cancelled after some of its 20 frames; the rerun rendered
    // the others and skipped those.
    let log = std::fs::read_to_string(work.join("log/render_2.out")).unwrap();
    assert!(log.contains("CANCELLED"), "{log}");
    match summaries(&log)[..] {
        [(rendered, skipped)] => {
            assert!(skipped > 0 && rendered > 0, "{log}");
            assert_eq!(rendered + skipped, sizes[1], "{log}");
        }
        _ => panic!("one finished attempt expected:\n{log}"),
    }
    for task in [1, 3] {
        let log = std::fs::read_to_string(work.join(format!("log/render_{task}.out"))).unwrap();
        assert_eq!(summaries(&log), [(sizes[task - 1], 0)], "{log}");
    }

    assert_eq!(probe(&work.join("video.mp4")), (320, 240, FRAMES));

    // `animate status` (SPEC §8) when this build has it; otherwise the frames' presence,
    // checked above, is what the folder can tell.
    // (`animate status --help` would print the render help, `status` read as a manifest.)
    let has_status = animate().args(["help", "status"]).output().unwrap();
    if has_status.status.success() {
        animate()
            .arg("status")
            .arg(work.join("anim.toml"))
            .arg("-o")
            .arg(work.join("frames"))
            .assert()
            .code(0);
    }
}
