//! Producing frames, from "which" to "where":
//!
//! - `select`: frame lists, `K/N` shards and `--shard auto` resolved from a render farm's
//!   environment;
//! - `run`: the render command as a library call (frames, destination, checks first);
//!   `policy`: what a run may keep or replace, and how its video is encoded;
//! - `pipeline`: rendering in parallel into a folder or a stream, reporting `events`;
//!   `found`: what a run makes of the files already under its frames' names;
//! - `provenance`: what made a frame, recorded in the frame file; `status`: which frames
//!   of a folder are up to date, stale or missing;
//! - `folder`: what else a frame folder holds (frames past the end, temporaries of
//!   killed runs) and `animate clean`; `lock`: one manifest at a time per folder;
//!   `claim`: runs of that manifest sharing the folder render each frame once; `owner`:
//!   whose a file under a frame's name is (runs, `clean` and `bless` touch only theirs);
//! - `video`: ffmpeg, checked before the first frame; `encode`: a rendered folder into a
//!   video; `tags`: its BT.709 matrix and colour tags;
//! - `balance`: shards of equal predicted cost from a small pre-pass; `estimate`: the
//!   predicted cost and time of a render; `cost`: what each frame cost, recorded beside
//!   it;
//! - `hooks`: the user's commands after each frame and after the run; `hook_process`:
//!   a hook's process group, waited for, stopped with the run or when its time is up,
//!   its output kept as a bounded tail; `hooked`: the reporter that counts a run's
//!   frames and lines the frame hooks up in its order.

pub mod balance;
pub mod claim;
pub mod cost;
pub mod encode;
pub mod estimate;
pub mod events;
pub mod folder;
mod found;
pub mod hook_process;
pub mod hooked;
pub mod hooks;
pub mod lock;
pub mod owner;
pub mod pipeline;
pub mod policy;
pub mod provenance;
pub mod run;
pub mod select;
pub mod status;
pub mod tags;
pub mod video;
