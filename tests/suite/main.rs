//! The integration tests, one test crate with a module per subject: every test file used to
//! be its own crate linking the whole workspace (49 of the 53 were compile and link time on
//! a fresh clone); one crate links once. Helpers shared by the modules: `support` (running
//! the built binaries, outside readers), `skip` (tests that need an outside tool say they
//! skipped, and fail under CI), `common` and `view_common`, `shipped` (the scenes and
//! manifests the repository ships).
//!
//! Run one subject with its module path: `cargo test --release --test suite farm_slurm`.

mod common;
mod shipped;
mod skip;
mod support;
mod view_common;

mod adaptive_aa;
mod animate_check;
mod animate_cli;
mod animate_encode;
mod animate_faults;
mod animate_ffmpeg;
mod animate_mesh_warnings;
mod animate_preview;
mod animate_provenance;
mod animate_records;
mod animate_reliability;
mod animate_tracks;
mod background_record;
mod balance;
mod camera_tracks;
mod check_bounded;
mod check_browser;
mod check_reports;
mod colour_tags;
mod csg_depth;
mod csg_properties;
mod degenerate_geometry;
mod degenerate_work;
mod directing;
mod docs_commands;
mod docs_examples;
mod embree_rays;
mod exit_status;
mod exr_frames;
mod exr_manifest;
mod exr_oracles;
mod ext_shape_properties;
mod ext_tracks;
mod farm_shard;
mod farm_slurm;
mod focus;
mod frame_cli;
mod frame_specs;
mod golden_frames;
mod image_povray;
mod image_textures;
mod interrupt;
mod lean_build;
mod light_names;
mod lights_povray;
mod malformed_scenes;
mod mesh_budgets;
mod mesh_data;
mod mesh_epsilon;
mod mesh_files;
mod mesh_normals;
mod mesh_placing;
mod mesh_povray;
mod messages;
mod newcomer;
mod newcomer_frictions;
mod nff;
mod nff_povray;
mod openjd_job;
mod pgo_build;
mod pixel_aspect;
mod povray_objects;
mod production_costs;
mod production_drafts;
mod production_encodes;
mod production_hooks;
mod production_loops;
mod production_shared;
mod progress;
mod provenance_inputs;
mod raytrace_cli;
mod raytrace_info;
mod readonly_folder;
mod reliability_four;
mod reliability_three;
mod robust_parsers;
mod scene_parsing;
mod shape_placing;
mod shape_properties;
mod shapes_povray;
mod shipped_files;
mod skip_visible;
mod spd_table;
mod tev_stream;
mod texture_scale;
mod tile_faces;
mod tracer_limits;
mod view_browser;
mod view_direct;
mod view_direct_browser;
mod view_limits;
mod view_server;
mod wide_frames;
