//! Tracks on a glTF scene's nodes (SPEC §18): `target = { node = "Front wheel", field =
//! "rotation" }`, fields `translation` and `scale` ([x, y, z]) and `rotation` ([x, y, z]
//! degrees about x, then y, then z, as §16's `rotate`); any node name, spaces included.
//! A node track's value is put into the node over the file's animation channel for that
//! field (the track wins), and the scene is posed again at every time.
//!
//! The manifest keeps such a target as the inline table's text (`written`), which is
//! what messages quote; `parse` reads it back.

use glam::{DQuat, DVec3, EulerRot};
use whitted::gltf::clip::Path;
use whitted::gltf::Put;
use whitted::scene::Scene;

/// The fields a node track may drive.
pub const FIELDS: [&str; 3] = ["translation", "rotation", "scale"];

/// A target table's canonical text.
pub fn written(node: &str, field: &str) -> String {
    let quote = |s: &str| toml::Value::String(s.to_string()).to_string();
    format!("{{ node = {}, field = {} }}", quote(node), quote(field))
}

/// The node name and field of a target written by `written`, if it is one.
pub fn parse(target: &str) -> Option<(String, String)> {
    if !target.starts_with("{ node = ") {
        return None;
    }
    let table: toml::Table = toml::from_str(&format!("t = {target}")).ok()?;
    let t = table.get("t")?.as_table()?;
    let node = t.get("node")?.as_str()?.to_string();
    let field = t.get("field")?.as_str()?.to_string();
    Some((node, field))
}

/// A track on a node, resolved against the scene's glTF file.
#[derive(Clone, Debug, PartialEq)]
pub struct NodeTrack {
    /// The node's index in the file.
    pub node: usize,
    /// The field.
    pub path: Path,
    /// The track's index among the manifest's tracks.
    pub track: usize,
}

/// Resolves `{ node, field }` against the glTF file of `scene`.
pub fn resolve(node: &str, field: &str, scene: &Scene, track: usize) -> Result<NodeTrack, String> {
    let Some(model) = &scene.model else {
        return Err(format!(
            "a track targets a node only in a glTF scene; `{node}` cannot be looked for in a Scene.txt or NFF file"
        ));
    };
    let path = match field {
        "translation" => Path::Translation,
        "rotation" => Path::Rotation,
        "scale" => Path::Scale,
        other => {
            return Err(format!(
                "unknown node field `{other}`: a node track drives {}",
                FIELDS.join(", ")
            ))
        }
    };
    let nodes = &model.rig.nodes;
    let found = nodes.iter().position(|n| n.name.as_deref() == Some(node));
    let index = found.ok_or_else(|| {
        let mut names: Vec<&str> = nodes.iter().filter_map(|n| n.name.as_deref()).collect();
        names.truncate(20);
        format!(
            "the glTF file has no node named `{node}`; its nodes include: {}",
            if names.is_empty() {
                "none named".to_string()
            } else {
                names.join(", ")
            }
        )
    })?;
    Ok(NodeTrack {
        node: index,
        path,
        track,
    })
}

impl NodeTrack {
    /// The value a track's `v` puts into the node.
    pub fn put(&self, v: DVec3) -> Put {
        let value = match self.path {
            Path::Rotation => {
                let [x, y, z] = v.to_array().map(f64::to_radians);
                let q = DQuat::from_euler(EulerRot::ZYX, z, y, x);
                q.to_array().to_vec()
            }
            _ => v.to_array().to_vec(),
        };
        Put {
            node: self.node,
            path: self.path,
            value,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_target_table_reads_back() {
        let t = written("Front \"wheel\"", "rotation");
        assert_eq!(
            parse(&t),
            Some(("Front \"wheel\"".into(), "rotation".into()))
        );
        assert_eq!(parse("sphere 1 center"), None);
    }

    #[test]
    fn rotation_is_degrees_about_x_then_y_then_z() {
        let track = NodeTrack {
            node: 0,
            path: Path::Rotation,
            track: 0,
        };
        // 90° about x then 90° about y: x ↦ x ↦ −z; y ↦ z ↦ x.
        let put = track.put(DVec3::new(90.0, 90.0, 0.0));
        let q = DQuat::from_slice(&put.value);
        assert!((q * DVec3::X - -DVec3::Z).length() < 1e-12);
        assert!((q * DVec3::Y - DVec3::X).length() < 1e-12);
    }
}
