//! Shards by hand: chunks, `K/N` and `auto` parsing, and every render farm's variables.

use super::*;

#[test]
fn shards_cover_everything_once_with_near_equal_sizes() {
    let all: Vec<u32> = (0..250).collect();
    for n in 1..=17 {
        let parts: Vec<Vec<u32>> = (0..n).map(|k| shard(&all, k, n)).collect();
        let joined: Vec<u32> = parts.concat();
        assert_eq!(joined, all, "n = {n}");
        let sizes: Vec<usize> = parts.iter().map(Vec::len).collect();
        let (min, max) = (sizes.iter().min().unwrap(), sizes.iter().max().unwrap());
        assert!(max - min <= 1, "{sizes:?}");
    }
    // 10 frames in 3 shards: 3, 3, 4.
    assert_eq!(shard(&(0..10).collect::<Vec<_>>(), 0, 3), vec![0, 1, 2]);
    assert_eq!(shard(&(0..10).collect::<Vec<_>>(), 2, 3), vec![6, 7, 8, 9]);
}

#[test]
fn shard_specs() {
    let part = |index, count| Shard::Part { index, count };
    assert_eq!("3/16".parse(), Ok(part(3, 16)));
    assert_eq!(" 0 / 1 ".parse(), Ok(part(0, 1)));
    assert_eq!("auto".parse(), Ok(Shard::Auto));
    for bad in ["16/16", "0/0", "1", "x/2", "-1/2", "Auto", ""] {
        assert_eq!(
            bad.parse::<Shard>(),
            Err(ShardError::Syntax(bad.into())),
            "{bad}"
        );
    }
}

/// An environment of the given variables only.
fn env(vars: &[(&str, &str)]) -> impl Fn(&str) -> Option<String> {
    let vars: Vec<(String, String)> = vars
        .iter()
        .map(|(k, v)| (k.to_string(), v.to_string()))
        .collect();
    move |name| vars.iter().find(|(k, _)| k == name).map(|(_, v)| v.clone())
}

fn auto(vars: &[(&str, &str)], count: Option<u32>) -> Result<(u32, u32), ShardError> {
    Shard::Auto.resolve(env(vars), count, "--shards")
}

fn slurm(
    id: &'static str,
    min: &'static str,
    n: &'static str,
) -> Vec<(&'static str, &'static str)> {
    vec![(SLURM_ID, id), (SLURM_MIN, min), (SLURM_COUNT, n)]
}

#[test]
fn slurm_arrays_from_zero_or_one_or_with_a_step() {
    // --array=0-15: task 5 is chunk 5 of 16.
    assert_eq!(auto(&slurm("5", "0", "16"), None), Ok((5, 16)));
    // --array=1-16: task 1 is chunk 0 and task 16 the last, 15.
    assert_eq!(auto(&slurm("1", "1", "16"), None), Ok((0, 16)));
    assert_eq!(auto(&slurm("16", "1", "16"), None), Ok((15, 16)));
    // --array=10-40:10 is tasks 10, 20, 30, 40: task 30 is (30 − 10) ÷ 10 = chunk 2.
    let mut v = slurm("30", "10", "4");
    v.push((SLURM_STEP, "10"));
    assert_eq!(auto(&v, None), Ok((2, 4)));
    // A count that agrees is accepted.
    assert_eq!(auto(&slurm("2", "0", "4"), Some(4)), Ok((2, 4)));
}

#[test]
fn slurm_errors_name_the_variables() {
    let e = auto(&slurm("2", "0", "4"), Some(8)).unwrap_err();
    assert_eq!(
        e.to_string(),
        "shard auto: SLURM_ARRAY_TASK_COUNT=4 tasks, but --shards 8"
    );
    let e = auto(&[(SLURM_ID, "3"), (SLURM_MIN, "0")], None).unwrap_err();
    assert_eq!(
        e.to_string(),
        "shard auto: SLURM_ARRAY_TASK_ID is set but SLURM_ARRAY_TASK_COUNT is not"
    );
    // --array=0,3,7 is three tasks, but task 7 is not chunk 7 of 3.
    let e = auto(&slurm("7", "0", "3"), None).unwrap_err();
    assert_eq!(
        e.to_string(),
        "shard auto: task index 7 (SLURM_ARRAY_TASK_ID=7 − SLURM_ARRAY_TASK_MIN=0) \
         is not below the task count 3 (SLURM_ARRAY_TASK_COUNT=3)"
    );
    // --array=10-40:10 has no task 25.
    let mut v = slurm("25", "10", "4");
    v.push((SLURM_STEP, "10"));
    let e = auto(&v, None).unwrap_err();
    assert!(e.to_string().contains("not a task of the array"), "{e}");
    let e = auto(&slurm("x", "0", "3"), None).unwrap_err();
    assert_eq!(
        e.to_string(),
        "shard auto: SLURM_ARRAY_TASK_ID=\"x\" is not a whole number"
    );
}

#[test]
fn kubernetes_and_aws_take_the_count_from_the_caller() {
    assert_eq!(auto(&[(K8S_INDEX, "7")], Some(8)), Ok((7, 8)));
    assert_eq!(auto(&[(AWS_INDEX, "0")], Some(3)), Ok((0, 3)));
    let e = auto(&[(K8S_INDEX, "7")], None).unwrap_err();
    assert_eq!(
        e.to_string(),
        "shard auto: JOB_COMPLETION_INDEX=7 gives this task's index but not the number \
         of tasks; give it with --shards N"
    );
    let e = auto(&[(AWS_INDEX, "8")], Some(8)).unwrap_err();
    assert_eq!(
        e.to_string(),
        "shard auto: task index 8 (AWS_BATCH_JOB_ARRAY_INDEX=8) is not below the task \
         count 8 (--shards 8)"
    );
}

#[test]
fn no_scheduler_or_several() {
    let e = auto(&[], Some(4)).unwrap_err();
    for var in [SLURM_ID, K8S_INDEX, AWS_INDEX] {
        assert!(e.to_string().contains(var), "{e}");
    }
    // An empty value is unset.
    assert_eq!(
        auto(&[(K8S_INDEX, "")], Some(4)),
        Err(ShardError::NoScheduler)
    );
    let e = auto(&[(K8S_INDEX, "1"), (AWS_INDEX, "2")], Some(4)).unwrap_err();
    assert_eq!(
        e.to_string(),
        "shard auto: more than one scheduler's task index is set \
         (JOB_COMPLETION_INDEX=1, AWS_BATCH_JOB_ARRAY_INDEX=2); unset the others"
    );
}

#[test]
fn a_given_shard_must_agree_with_the_count() {
    let part = Shard::Part {
        index: 3,
        count: 16,
    };
    assert_eq!(part.resolve(env(&[]), None, "--shards"), Ok((3, 16)));
    assert_eq!(part.resolve(env(&[]), Some(16), "--shards"), Ok((3, 16)));
    let e = part.resolve(env(&[]), Some(8), "--shards").unwrap_err();
    assert_eq!(e.to_string(), "shard 3/16: 16 tasks, but --shards 8");
    // The environment is not read for K/N.
    let slurm = slurm("0", "0", "2");
    assert_eq!(part.resolve(env(&slurm), None, "-n"), Ok((3, 16)));
}

#[test]
fn task_counts_are_bounded_and_slurm_ids_do_not_wrap() {
    // Reliability round three: 1/4294967295 took gigabytes in --balance; Slurm's arithmetic wrapped.
    let e = "1/4294967295".parse::<Shard>().unwrap_err();
    let limit = "the number of tasks must be from 1 to 1000000, the limit of shards";
    assert_eq!(e.to_string(), format!("shard 1/4294967295: {limit}"));
    assert!("1/1000000".parse::<Shard>().is_ok());
    let e = auto(&slurm("0", "0", "4294967297"), None).unwrap_err();
    assert!(matches!(e, ShardError::Count { .. }), "{e}");
    let e = auto(&slurm("0", "0", "-3"), None).unwrap_err();
    assert!(e.to_string().contains("SLURM_ARRAY_TASK_COUNT=-3"), "{e}");
    let v = slurm("9223372036854775807", "-9223372036854775808", "4");
    let e = auto(&v, None).unwrap_err();
    assert!(matches!(e, ShardError::OutOfRange { index: -1, .. }), "{e}");
    let e = auto(&[(K8S_INDEX, "0")], Some(0)).unwrap_err();
    assert!(matches!(e, ShardError::Count { .. }), "{e}");
}
