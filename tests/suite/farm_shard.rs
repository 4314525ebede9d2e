//! `animate --shard auto` end to end: the task index from a Slurm array job, a Kubernetes
//! Indexed Job or an AWS Batch array job's environment (SPEC §9), and the errors when the
//! environment says nothing or disagrees with `--shards`.

use crate::support;

use assert_cmd::Command;
use support::*;

const INDEX_VARS: [&str; 5] = [
    "SLURM_ARRAY_TASK_ID",
    "SLURM_ARRAY_TASK_MIN",
    "SLURM_ARRAY_TASK_COUNT",
    "JOB_COMPLETION_INDEX",
    "AWS_BATCH_JOB_ARRAY_INDEX",
];

/// `animate` with no scheduler variable inherited from the test's own environment, then
/// `vars` set.
fn task(vars: &[(&str, String)]) -> Command {
    let mut cmd = animate();
    for var in INDEX_VARS.iter().chain(&["SLURM_ARRAY_TASK_STEP"]) {
        cmd.env_remove(var);
    }
    for (k, v) in vars {
        cmd.env(k, v);
    }
    cmd
}

fn names(dir: &std::path::Path) -> Vec<String> {
    files(dir).into_iter().map(|(n, _)| n).collect()
}

#[test]
fn a_slurm_array_from_one_renders_the_full_run() {
    let (dir, manifest) = project(&circle_manifest(""));
    render_into(&manifest, &dir.path().join("full"), &[]);
    let out = dir.path().join("farm");
    // sbatch --array=1-3: tasks 1, 2, 3 are chunks 0, 1, 2 of the 12 frames.
    for id in 1..=3 {
        let vars = [
            ("SLURM_ARRAY_TASK_ID", id.to_string()),
            ("SLURM_ARRAY_TASK_MIN", "1".to_string()),
            ("SLURM_ARRAY_TASK_COUNT", "3".to_string()),
        ];
        task(&vars)
            .arg(&manifest)
            .args(["--shard", "auto", "--resume", "-o"])
            .arg(&out)
            .assert()
            .success();
        assert_eq!(files(&out).len(), 4 * id);
    }
    assert_eq!(files(&out), files(&dir.path().join("full")));
}

#[test]
fn kubernetes_and_aws_indices_with_a_count() {
    let (dir, manifest) = project(&circle_manifest(""));
    for (var, out) in [
        ("JOB_COMPLETION_INDEX", "k8s"),
        ("AWS_BATCH_JOB_ARRAY_INDEX", "aws"),
    ] {
        let out = dir.path().join(out);
        task(&[(var, "1".to_string())])
            .arg(&manifest)
            .args(["--shard", "auto", "--shards", "3", "-o"])
            .arg(&out)
            .assert()
            .success();
        // Chunk 1 of 3 over frames 0..12 is 4..8.
        let want: Vec<String> = (4..8).map(|f| format!("frame_{f:04}.png")).collect();
        assert_eq!(names(&out), want, "{var}");
    }
}

/// Runs `animate MANIFEST ARGS` under `vars`, expects exit 2 and no frame folder, and
/// returns standard error.
fn fails(vars: &[(&str, String)], args: &[&str]) -> String {
    let (dir, manifest) = project(&circle_manifest(""));
    let out = task(vars)
        .arg(&manifest)
        .args(args)
        .arg("-o")
        .arg(dir.path().join("frames"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2), "{args:?}");
    assert!(!dir.path().join("frames").exists());
    String::from_utf8_lossy(&out.stderr).into_owned()
}

#[test]
fn auto_without_a_scheduler_names_the_variables() {
    let err = fails(&[], &["--shard", "auto", "--shards", "4"]);
    for var in [
        "SLURM_ARRAY_TASK_ID",
        "JOB_COMPLETION_INDEX",
        "AWS_BATCH_JOB_ARRAY_INDEX",
    ] {
        assert!(err.contains(var), "{err}");
    }
}

#[test]
fn a_missing_or_disagreeing_count_is_an_error() {
    let err = fails(
        &[("AWS_BATCH_JOB_ARRAY_INDEX", "2".into())],
        &["--shard", "auto"],
    );
    assert!(
        err.contains("AWS_BATCH_JOB_ARRAY_INDEX=2") && err.contains("--shards N"),
        "{err}"
    );
    let slurm = [
        ("SLURM_ARRAY_TASK_ID", "0".to_string()),
        ("SLURM_ARRAY_TASK_MIN", "0".to_string()),
        ("SLURM_ARRAY_TASK_COUNT", "4".to_string()),
    ];
    let err = fails(&slurm, &["--shard", "auto", "--shards", "3"]);
    assert!(
        err.contains("SLURM_ARRAY_TASK_COUNT=4") && err.contains("--shards 3"),
        "{err}"
    );
    let err = fails(&[], &["--shard", "1/4", "--shards", "3"]);
    assert!(err.contains("shard 1/4: 4 tasks, but --shards 3"), "{err}");
    // An index past the count.
    let err = fails(
        &[("JOB_COMPLETION_INDEX", "3".into())],
        &["--shard", "auto", "--shards", "3"],
    );
    assert!(err.contains("JOB_COMPLETION_INDEX=3"), "{err}");
    // The count alone means nothing.
    fails(&[], &["--shards", "3"]);
}
