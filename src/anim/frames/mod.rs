//! Producing frames: which frames a run renders (`select`: frame lists, `K/N` shards and
//! `--shard auto` resolved from a render farm's environment).

pub mod select;
