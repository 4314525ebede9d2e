//! The bounds every frame's values are held to, checked when a timeline is built: each
//! track's value alone (SPEC §1's bounds, `Target::check`), and each extension record a
//! track changes, with all of its tracks at once (the reader's bounds, §16).

use super::bind::invalid;
use super::target::{self, Field};
use super::{Kind, Timeline, Track};
use crate::refusal::ManifestError;

impl Timeline {
    /// Every extension record a track changes, with all its tracks' values at every time a
    /// frame samples, within the bounds the reader applies (Min below Max, r below R,
    /// Radius below Falloff…): the track of the field to blame is named, or the record's
    /// first track when the bound is the record's as a whole.
    pub(super) fn check_records(&self) -> Result<(), ManifestError> {
        let record_of = |t: &Track| match t.target.field {
            Field::Ext(f) => Some(f.record),
            _ => None,
        };
        for (n, track) in self.tracks.iter().enumerate() {
            let Some(record) = record_of(track) else {
                continue;
            };
            if self.tracks[..n]
                .iter()
                .any(|t| record_of(t) == Some(record))
            {
                continue;
            }
            let mine: Vec<(usize, &Track)> = (self.tracks.iter().enumerate())
                .filter(|(_, t)| record_of(t) == Some(record))
                .collect();
            for frame in 0..self.frames {
                for t in self.times(frame) {
                    let mut ext = self.base.ext.clone();
                    for (_, other) in &mine {
                        if let Field::Ext(f) = other.target.field {
                            target::ext::write(&mut ext, &f, self.value(other, t));
                        }
                    }
                    let Err(why) = target::ext::check_record(&ext, record) else {
                        continue;
                    };
                    let blamed = why.field.to_lowercase();
                    let &(k, culprit) = mine
                        .iter()
                        .find(|(_, o)| matches!(o.target.field, Field::Ext(f) if f.name == blamed))
                        .unwrap_or(&mine[0]);
                    let at = if t == f64::from(frame) {
                        format!("frame {frame}")
                    } else {
                        format!("frame {frame} (motion-blur time {t})")
                    };
                    let message = format!(
                        "track {} (`{}`): at {at} the record is out of bounds: {}",
                        k + 1,
                        culprit.spec.target,
                        why.message
                    );
                    let loc = self.loc_of(culprit, t);
                    return Err(invalid(loc, message));
                }
            }
        }
        Ok(())
    }

    /// Every value of every track, at every time a frame samples, within SPEC §1's bounds.
    pub(super) fn check_values(&self) -> Result<(), ManifestError> {
        for (n, track) in self.tracks.iter().enumerate() {
            for frame in 0..self.frames {
                for t in self.times(frame) {
                    let value = self.value(track, t);
                    if let Err(why) = track.target.check(value) {
                        let shown = match track.target.kind() {
                            Kind::Number => format!("{}", value.x),
                            Kind::Vector => format!("[{}, {}, {}]", value.x, value.y, value.z),
                        };
                        let at = if t == f64::from(frame) {
                            format!("frame {frame}")
                        } else {
                            format!("frame {frame} (motion-blur time {t})")
                        };
                        let message = format!(
                            "track {} (`{}`): at {at} its value {shown} is out of bounds: {why}",
                            n + 1,
                            track.spec.target
                        );
                        let loc = self.loc_of(track, t);
                        return Err(invalid(loc, message));
                    }
                }
            }
        }
        Ok(())
    }

    /// The manifest place of the key that gives `track` its value at `t`.
    fn loc_of<'a>(&self, track: &'a Track, t: f64) -> &'a whitted::fileloc::FileLoc {
        let (motion, frames) = (&track.spec.motion, self.frames);
        match self.looped {
            true => motion.loc_looped(t, frames, &track.spec.loc),
            false => motion.loc_at(t, &track.spec.loc),
        }
    }
}
