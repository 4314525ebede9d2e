//! The file's animations read into `Clip`s: each channel's key times and values from its
//! sampler's accessors, checked (increasing finite times, as many values as the keys and
//! the interpolation need, all keys of the file within `MAX_KEYS`) before they are kept.

use super::accessor::Buffers;
use super::clip::{Channel, Clip, Interp, Path, MAX_KEYS};
use super::error::{at, GltfError};
use super::rig::Rig;
use gltf::animation::{Interpolation, Property};

/// Every animation of `doc`, its keys checked: increasing finite times, as many values
/// as the keys and the interpolation need.
pub fn read(doc: &gltf::Document, b: &Buffers, rig: &Rig) -> Result<Vec<Clip>, GltfError> {
    let mut keys = 0u64;
    let mut clips = Vec::new();
    for anim in doc.animations() {
        let mut channels = Vec::new();
        for ch in anim.channels() {
            let path = format!("animations[{}].channels[{}]", anim.index(), ch.index());
            let sampler = ch.sampler();
            let input = sampler.input();
            let times: Vec<f64> = b
                .floats::<1>(&input, MAX_KEYS - keys)?
                .into_iter()
                .map(|[t]| t)
                .collect();
            keys += times.len() as u64;
            if times.iter().any(|t| !t.is_finite()) || times.windows(2).any(|w| w[1] <= w[0]) {
                return Err(at(
                    &rig.file,
                    format!("accessors[{}]", input.index()),
                    "key times must be finite and increasing",
                ));
            }
            let target = ch.target();
            let node = target.node().index();
            let (path_kind, width) = match target.property() {
                Property::Translation => (Path::Translation, 3),
                Property::Rotation => (Path::Rotation, 4),
                Property::Scale => (Path::Scale, 3),
                Property::MorphTargetWeights => {
                    let targets = rig.nodes[node]
                        .mesh
                        .and_then(|m| rig.meshes[m].first())
                        .map_or(0, |p| p.targets.len());
                    (Path::Weights, targets)
                }
            };
            let interp = match sampler.interpolation() {
                Interpolation::Linear => Interp::Linear,
                Interpolation::Step => Interp::Step,
                Interpolation::CubicSpline => Interp::Cubic,
            };
            let groups = if interp == Interp::Cubic { 3 } else { 1 };
            let need = times.len() * groups * width;
            let output = sampler.output();
            let budget = MAX_KEYS * 16;
            let values: Vec<f64> = match width {
                3 if path_kind != Path::Weights => b
                    .floats::<3>(&output, budget)?
                    .into_iter()
                    .flatten()
                    .collect(),
                4 if path_kind == Path::Rotation => b
                    .floats::<4>(&output, budget)?
                    .into_iter()
                    .flatten()
                    .collect(),
                _ => b
                    .floats::<1>(&output, budget)?
                    .into_iter()
                    .flatten()
                    .collect(),
            };
            if values.len() != need || width == 0 {
                return Err(at(
                    &rig.file,
                    format!("{path}.sampler"),
                    format!(
                        "{} values for {} keys of {width} each ({interp:?})",
                        values.len(),
                        times.len()
                    ),
                ));
            }
            channels.push(Channel {
                node,
                path: path_kind,
                interp,
                times,
                values,
                width,
            });
        }
        clips.push(Clip {
            name: anim.name().map(str::to_string),
            channels,
        });
    }
    Ok(clips)
}
