//! Shards: the K-th of N contiguous chunks of a run's frames (0-based, sizes differing by
//! at most one), written `K/N`, or `auto`: the task's index from the render farm's
//! environment (SPEC §9):
//!
//! ```text
//! Slurm array job          SLURM_ARRAY_TASK_ID − SLURM_ARRAY_TASK_MIN (÷ SLURM_ARRAY_TASK_STEP)
//!                          of SLURM_ARRAY_TASK_COUNT
//! Kubernetes Indexed Job   JOB_COMPLETION_INDEX       of the count the user gives
//! AWS Batch array job      AWS_BATCH_JOB_ARRAY_INDEX  of the count the user gives
//! ```

use std::str::FromStr;

/// Why a shard cannot be parsed or resolved. `count_name` is how the caller lets the user
/// give the task count (the binary passes its option's name).
#[derive(Debug, thiserror::Error, PartialEq, Eq)]
pub enum ShardError {
    /// The text is neither `K/N` with 0 ≤ K < N nor `auto` (the text as given).
    #[error("shard {0:?}: expected K/N with 0 ≤ K < N, as in 3/16, or auto")]
    Syntax(String),
    /// `auto`, and none of the known schedulers' index variables is set.
    #[error(
        "shard auto: no scheduler's task index is set: none of SLURM_ARRAY_TASK_ID (Slurm \
         array job), JOB_COMPLETION_INDEX (Kubernetes Indexed Job), AWS_BATCH_JOB_ARRAY_INDEX \
         (AWS Batch array job)"
    )]
    NoScheduler,
    /// `auto`, and the index variables of several schedulers are set (listed as
    /// `VAR=value, ...`).
    #[error("shard auto: more than one scheduler's task index is set ({0}); unset the others")]
    Several(String),
    /// `auto`, and a scheduler's variable holds something other than a whole number.
    #[error("shard auto: {var}={value:?} is not a whole number")]
    NotANumber {
        /// The variable's name.
        var: &'static str,
        /// Its value.
        value: String,
    },
    /// `auto` under Slurm, and a variable the index needs is not set.
    #[error("shard auto: {var} is set but {missing} is not")]
    Missing {
        /// The variable that is set.
        var: &'static str,
        /// The variable that is missing.
        missing: &'static str,
    },
    /// `auto` under Kubernetes or AWS Batch (which give only the index), and the caller
    /// gave no task count.
    #[error(
        "shard auto: {var}={index} gives this task's index but not the number of tasks; \
         give it with {count_name} N"
    )]
    NoCount {
        /// The index variable that is set.
        var: &'static str,
        /// Its value.
        index: u32,
        /// How the caller lets the user give the count.
        count_name: String,
    },
    /// The caller gave a task count that differs from the shard's own.
    #[error("shard {shard}: {from} tasks, but {count_name} {count}")]
    Disagree {
        /// The shard as written (`3/16` or `auto`).
        shard: String,
        /// Where the shard's own count comes from, e.g. `16` or `SLURM_ARRAY_TASK_COUNT=4`.
        from: String,
        /// How the caller lets the user give the count.
        count_name: String,
        /// The count the user gave.
        count: u32,
    },
    /// `auto`, and the index from the environment is not below the count (e.g. a Slurm
    /// array with gaps).
    #[error("shard auto: task index {index} ({from}) is not below the task count {count} ({of})")]
    OutOfRange {
        /// The task index worked out from the environment.
        index: i64,
        /// The variables it came from, with their values.
        from: String,
        /// The task count.
        count: u32,
        /// Where the count came from.
        of: String,
    },
    /// A task count of 0 or past `limits::MAX_SHARDS` (`from` says where it came from:
    /// `3/4294967295`, `SLURM_ARRAY_TASK_COUNT=…`, `--shards …`).
    #[error(
        "shard {from}: the number of tasks must be from 1 to {}, the limit of shards",
        whitted::limits::MAX_SHARDS
    )]
    Count {
        /// The count as given, with where it came from.
        from: String,
    },
}

/// A task count within `1..=limits::MAX_SHARDS`, or the error naming `from`.
pub fn bounded_count(count: i128, from: impl FnOnce() -> String) -> Result<u32, ShardError> {
    match u32::try_from(count) {
        Ok(n) if (1..=whitted::limits::MAX_SHARDS).contains(&n) => Ok(n),
        _ => Err(ShardError::Count { from: from() }),
    }
}

/// Which part of the frames a task renders.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shard {
    /// Chunk `index` of `count` (`K/N`).
    Part {
        /// Which chunk, 0-based, below `count`.
        index: u32,
        /// How many chunks, 1 or more.
        count: u32,
    },
    /// The index (and for Slurm the count) from the scheduler's environment.
    Auto,
}

impl FromStr for Shard {
    type Err = ShardError;

    fn from_str(spec: &str) -> Result<Shard, ShardError> {
        if spec.trim() == "auto" {
            return Ok(Shard::Auto);
        }
        let bad = || ShardError::Syntax(spec.to_string());
        let (k, n) = spec.split_once('/').ok_or_else(bad)?;
        let index: u32 = k.trim().parse().map_err(|_| bad())?;
        let count: u64 = n.trim().parse().map_err(|_| bad())?;
        if count == 0 || u64::from(index) >= count {
            return Err(bad());
        }
        let count = bounded_count(count.into(), || spec.trim().to_string())?;
        Ok(Shard::Part { index, count })
    }
}

const SLURM_ID: &str = "SLURM_ARRAY_TASK_ID";
const SLURM_MIN: &str = "SLURM_ARRAY_TASK_MIN";
const SLURM_STEP: &str = "SLURM_ARRAY_TASK_STEP";
const SLURM_COUNT: &str = "SLURM_ARRAY_TASK_COUNT";
const K8S_INDEX: &str = "JOB_COMPLETION_INDEX";
const AWS_INDEX: &str = "AWS_BATCH_JOB_ARRAY_INDEX";

impl Shard {
    /// This task's (index, count). `env` looks a variable up (an empty value counts as
    /// unset); `count` is the task count the user gave, if any, which must agree with the
    /// shard's own; `count_name` names it in messages.
    pub fn resolve(
        self,
        env: impl Fn(&str) -> Option<String>,
        count: Option<u32>,
        count_name: &str,
    ) -> Result<(u32, u32), ShardError> {
        let disagree = |shard: &str, from: String, given: u32| ShardError::Disagree {
            shard: shard.to_string(),
            from,
            count_name: count_name.to_string(),
            count: given,
        };
        let Shard::Part { index, count: n } = self else {
            let env = Vars(&env);
            let task = match env.scheduler()? {
                (SLURM_ID, id) => env.slurm(id)?,
                (var, index) => {
                    let n = count.ok_or_else(|| ShardError::NoCount {
                        var,
                        index: u32::try_from(index).unwrap_or(u32::MAX),
                        count_name: count_name.to_string(),
                    })?;
                    let n = bounded_count(n.into(), || format!("auto: {count_name} {n}"))?;
                    let of = format!("{count_name} {n}");
                    (index, format!("{var}={index}"), n, of)
                }
            };
            let (index, from, n, of) = task;
            if let Some(given) = count.filter(|&c| c != n) {
                return Err(disagree("auto", of, given));
            }
            return match u32::try_from(index) {
                Ok(k) if k < n => Ok((k, n)),
                _ => Err(ShardError::OutOfRange {
                    index,
                    from,
                    count: n,
                    of,
                }),
            };
        };
        match count {
            Some(given) if given != n => {
                Err(disagree(&format!("{index}/{n}"), n.to_string(), given))
            }
            _ => Ok((index, n)),
        }
    }
}

/// A task's index, how it was computed, the task count, and where that came from.
type Task = (i64, String, u32, String);

/// The environment `auto` reads.
struct Vars<'a, F: Fn(&str) -> Option<String>>(&'a F);

impl<F: Fn(&str) -> Option<String>> Vars<'_, F> {
    /// A variable's whole-number value, `None` when unset or empty.
    fn num(&self, var: &'static str) -> Result<Option<i64>, ShardError> {
        let Some(value) = (self.0)(var).filter(|v| !v.trim().is_empty()) else {
            return Ok(None);
        };
        match value.trim().parse() {
            Ok(n) => Ok(Some(n)),
            Err(_) => Err(ShardError::NotANumber { var, value }),
        }
    }

    /// The one scheduler index variable that is set, and its value.
    fn scheduler(&self) -> Result<(&'static str, i64), ShardError> {
        let mut set = Vec::new();
        for var in [SLURM_ID, K8S_INDEX, AWS_INDEX] {
            if let Some(v) = self.num(var)? {
                set.push((var, v));
            }
        }
        match set[..] {
            [one] => Ok(one),
            [] => Err(ShardError::NoScheduler),
            _ => {
                let list: Vec<String> = set.iter().map(|(v, x)| format!("{v}={x}")).collect();
                Err(ShardError::Several(list.join(", ")))
            }
        }
    }

    /// A Slurm array task: (ID − MIN) ÷ STEP of COUNT; -1 for an ID off the step.
    fn slurm(&self, id: i64) -> Result<Task, ShardError> {
        let require = |missing| {
            self.num(missing)?.ok_or(ShardError::Missing {
                var: SLURM_ID,
                missing,
            })
        };
        let min = require(SLURM_MIN)?;
        let total = require(SLURM_COUNT)?;
        let step = self.num(SLURM_STEP)?.unwrap_or(1).max(1);
        let mut from = format!("{SLURM_ID}={id} − {SLURM_MIN}={min}");
        if step > 1 {
            from = format!("({from}) ÷ {SLURM_STEP}={step}");
        }
        // In i128: ID − MIN of two i64 cannot wrap there.
        let offset = i128::from(id) - i128::from(min);
        let step = i128::from(step);
        let index = match offset % step == 0 {
            true => i64::try_from(offset / step).unwrap_or(-1),
            false => -1,
        };
        if index < 0 {
            from.push_str(", not a task of the array");
        }
        let of = format!("{SLURM_COUNT}={total}");
        let n = bounded_count(total.into(), || format!("auto: {of}"))?;
        Ok((index, from, n, of))
    }
}

/// The process environment, for [`Shard::resolve`].
pub fn process_env(var: &str) -> Option<String> {
    std::env::var(var).ok()
}

/// The K-th of N contiguous chunks of `frames`: chunk k is `frames[k·L/N .. (k+1)·L/N]`.
pub fn shard(frames: &[u32], k: u32, n: u32) -> Vec<u32> {
    let len = frames.len() as u64;
    let start = (k as u64 * len / n as u64) as usize;
    let end = ((k as u64 + 1) * len / n as u64) as usize;
    frames[start..end].to_vec()
}

#[cfg(test)]
mod tests;
