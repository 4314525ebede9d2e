//! The frame number in `[output] name`, in the spellings of the tools artists use, all
//! turned into Blender's run of `#` (one digit each, widened to the digits of the last
//! frame so that names sort):
//!
//! ```text
//! frame_####     Blender, fileseq      4 digits
//! frame_@@@@     fileseq, Nuke          4 digits (one each)
//! frame_%04d     ffmpeg, Nuke, printf   4 digits; %d alone is 4 too
//! frame_$F4      Houdini                4 digits; $F alone is 1
//! ```
//!
//! One frame number per name: mixing spellings, or two of `@`/`%d`/`$F`, is refused; any
//! other `%` conversion is refused.

/// `name` with its frame number spelt as a run of `#`, or why it cannot be.
pub fn to_hashes(name: &str) -> Result<String, String> {
    let mut out = String::with_capacity(name.len());
    let (mut converted, mut rest) = (0, name);
    while let Some(c) = rest.chars().next() {
        let digits = |s: &str| s.chars().take_while(char::is_ascii_digit).count();
        if c == '@' {
            let run = rest.chars().take_while(|&c| c == '@').count();
            out.push_str(&"#".repeat(run));
            rest = &rest[run..];
            converted += 1;
        } else if let Some(after) = rest.strip_prefix("$F") {
            let n = digits(after);
            let width = after[..n].parse::<usize>().unwrap_or(1).clamp(1, 32);
            out.push_str(&"#".repeat(width));
            rest = &after[n..];
            converted += 1;
        } else if let Some(after) = rest.strip_prefix('%') {
            let n = digits(after);
            let Some(tail) = after[n..].strip_prefix('d') else {
                return Err(format!(
                    "`name` {name:?}: the only printf conversion understood is %0Nd (the frame number); or write #### for it"
                ));
            };
            let width = after[..n]
                .trim_start_matches('0')
                .parse::<usize>()
                .unwrap_or(4);
            out.push_str(&"#".repeat(width.clamp(1, 32)));
            rest = tail;
            converted += 1;
        } else {
            out.push(c);
            rest = &rest[c.len_utf8()..];
        }
    }
    let runs = out.split(|c| c != '#').filter(|r| !r.is_empty()).count();
    if converted > 0 && runs > 1 {
        return Err(format!(
            "`name` {name:?} gives the frame number twice: use one ####, @@@@, %04d or $F4"
        ));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::to_hashes;

    #[test]
    fn every_spelling_becomes_hashes() {
        for (name, want) in [
            ("img_%04d", "img_####"),
            ("%d-shot", "####-shot"),
            ("f%6d", "f######"),
            ("frame_####", "frame_####"),
            ("frame_@@@@", "frame_####"),
            ("frame_@.exr", "frame_#.exr"),
            ("shot_$F4_v2", "shot_####_v2"),
            ("shot_$F", "shot_#"),
            ("cost_$5", "cost_$5"),
            ("a#b##", "a#b##"),
        ] {
            assert_eq!(to_hashes(name).as_deref(), Ok(want), "{name}");
        }
        for bad in ["img_%s", "a%04d_%04d", "##_%04d", "@@_$F4", "#_@", "x%"] {
            assert!(to_hashes(bad).is_err(), "{bad}");
        }
    }
}
