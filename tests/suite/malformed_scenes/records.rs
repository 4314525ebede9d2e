//! The table's second half: the fog, the camera and Ior out of range, then records cut
//! short, in excess or forgotten by the counts, bytes that are not text, and files that
//! hold nothing.

use super::*;

pub(super) fn cases() -> Vec<Case> {
    let mut non_utf8 = b"40 30\n0 2 10   # cam@".to_vec();
    non_utf8.push(0xE9); // 'é' in Latin-1
    non_utf8.extend_from_slice(b"ra\n0 1 0\n0 20\n0 0 0 0\n");
    let mut raw_byte = b"40 30\n0 2 @".to_vec();
    raw_byte.extend_from_slice(&[0xFF, b'1', b'0']);
    raw_byte.extend_from_slice(b"\n0 1 0\n0 20\n0 0 0 0\n");
    vec![
        case(
            "Ior 0",
            &[
                "40 30",
                "0 2 10",
                "0 1 0",
                "0 20",
                "1 0 0 1",
                "1 0 1 0   1 1 0 0   0.1 0.2 0.7 @0 0 0",
                LIGHT,
            ],
            "sphere 1 of 1, material, field Ior",
            "Ior must be greater than 0",
        ),
        case(
            "unknown fog type",
            &["40 30", "0 2 10", "0 1 0", "@4 20", "0 0 0 0"],
            "fog, field FogType",
            "0 (none), 1, 2 or 3",
        ),
        case(
            "fog distance 0 with fog",
            &["40 30", "0 2 10", "0 1 0", "1 @0", "0 0 0 0"],
            "fog, field FogDistance",
            "FogDistance must be greater than 0",
        ),
        case(
            "negative fog distance with fog",
            &["40 30", "0 2 10", "0 1 0", "3    @-5.5", "0 0 0 0"],
            "fog, field FogDistance",
            "FogDistance must be greater than 0",
        ),
        case(
            "camera on the look-at point",
            &["40 30", "0 2 10", "@0.0 2.0 1e1", "0 20", "0 0 0 0"],
            "point looked at, field x",
            "the camera is placed on the point it looks at",
        ),
        case(
            "end of file mid-sphere, in its texture",
            &[
                "40 30",
                "0 2 10",
                "0 1 0",
                "0 20",
                "2 0 0 1",
                SPHERE,
                "1.0 0.0 2.0 9.0 2 2 0.5 0.5 0.5@",
                "",
            ],
            "sphere 2 of 2, texture, field C2.r",
            "found the end of the file",
        ),
        case(
            "end of file mid-sphere, after blanks and a comment",
            &[
                "40 30",
                "0 2 10",
                "0 1 0",
                "0 20",
                "1 0 0 1",
                "1 0 1@   # the centre is cut short\n   ",
            ],
            "sphere 1 of 1, field Cz",
            "found the end of the file",
        ),
        case(
            "too few lights",
            &[
                "40 30", "0 2 10", "0 1 0", "0 20", "1 1 1 2", SPHERE, PLANE, CYLINDER,
                "5 10 5  1 1 1  1@", "",
            ],
            "light 2 of 2, field Lx",
            "found the end of the file",
        ),
        case(
            "extra tokens after the last light",
            &[
                "40 30", "0 2 10", "0 1 0", "0 20", "1 1 1 1", SPHERE, PLANE, CYLINDER, LIGHT,
                "  @oops",
            ],
            "after the last light",
            "unknown keyword 'oops'",
        ),
        // Issue 16 item 4: a record that runs into the next section is put on the count
        // that announced it, saying what the count announced.
        case(
            "a second light the counts forgot",
            &[
                "40 30",
                "0 2 10",
                "0 1 0",
                "0 20",
                "1 1 1 @1",
                SPHERE,
                PLANE,
                CYLINDER,
                LIGHT,
                "# a second light the counts forgot",
                "  -5 10 5  1 1 1  1",
            ],
            "counts, field NLights",
            "the counts announce 1 light, but line 11, after the last record, holds 7 values, as a light does: should NLights be 2",
        ),
        case(
            "five spheres announced, four given",
            &[
                "40 30", "0 2 10", "0 1 0", "0 20", "@5 1 0 1", SPHERE, SPHERE, SPHERE, SPHERE,
                PLANE, LIGHT,
            ],
            "counts, field NSpheres",
            "the counts announce 5 spheres, but line 10, read as sphere 5 of 5, holds 16 values, as a plane does: is a sphere missing, or should NSpheres be 4? (the error there, 10:1: Radius must be greater than 0, found '0')",
        ),
        case(
            "a sphere the counts forgot, read as a cylinder",
            &[
                "40 30", "0 2 10", "0 1 0", "0 20", "@1 0 1 1", SPHERE, SPHERE, CYLINDER, LIGHT,
            ],
            "counts, field NSpheres",
            "the counts announce 1 sphere, but line 7, read as cylinder 1 of 1, holds 14 values, as a sphere does: should NSpheres be 2, or is this sphere out of place?",
        ),
        case(
            "a wrong record that fits no kind stays where it is",
            &[
                "40 30", "0 2 10", "0 1 0", "0 20", "2 0 0 0", SPHERE, "@-1 0 1 0   1 1 0 0   0.7 0.3 0 1 0",
            ],
            "sphere 2 of 2, field Radius",
            "Radius must be greater than 0",
        ),
        Case {
            name: "a Latin-1 byte in a comment",
            src: non_utf8,
            context: "byte that cannot be read",
            message: "not UTF-8",
        },
        Case {
            name: "a stray 0xFF byte",
            src: raw_byte,
            context: "byte that cannot be read",
            message: "not UTF-8",
        },
        // A value missing from a record's line: at the end of that line, however far on
        // the error surfaces (in the header, the next record, two records on).
        case(
            "a camera position short of z",
            &["40 30", "0 2@", "0 1 0", "0 20", "0 0 0 0"],
            "camera position, field z",
            "z is missing at the end of this line: the camera position has 2 values here, so reading on took '0' from line 3 for it (and then failed at 4:3: expected 0 (none), 1, 2 or 3 for FogType, found '20')",
        ),
        case(
            "a sphere short of its BumpValue",
            &[
                "40 30", "0 2 10", "0 1 0", "0 20", "2 0 0 1", "1 0 1 0   1 1 0 0   0.7 0.3 0 1 0@",
                SPHERE, LIGHT,
            ],
            "sphere 1 of 2, material, field BumpValue",
            "BumpValue is missing at the end of this line: the sphere 1 of 2 has 13 values here, so reading on took '1' from line 7",
        ),
        case(
            "a cylinder short of a value, failing two lines on",
            &[
                "40 30", "0 2 10", "0 1 0", "0 20", "0 0 1 2",
                "0 1 0  3 0 -2  0.5   1 0 1 0   0.8 0 0 1 0@", LIGHT, "-6 8 4  0.6 0.6 0.8  0.6",
            ],
            "cylinder 1 of 1, material, field BumpValue",
            "reading on took '5' from line 7 for it (and then failed at 8:1: Intensity must be from 0 to 1000, found '-6')",
        ),
        case(
            "records laid out otherwise keep the error at its token",
            &["40 30 0 2 10 0 1 0", "1 @-5", "0 0 0 0"],
            "fog, field FogDistance",
            "FogDistance must be greater than 0 with fog, found '-5'",
        ),
        case(
            "a record written over two lines is not a missing value",
            &[
                "40 30", "0 2 10", "0 1 0", "0 20", "2 0 0 1", "1 0 1 0   1 1 0 0",
                "0.7 0.3 0 1 0 0", "@-1 0 1 0   1 1 0 0   0.7 0.3 0 1 0 0", LIGHT,
            ],
            "sphere 2 of 2, field Radius",
            "Radius must be greater than 0, found '-1'",
        ),
        case(
            "an empty file",
            &["@"],
            "resolution, field ResX",
            "found the end of the file",
        ),
        case(
            "a file of comments only",
            &["# Scene.txt", "  # nothing yet", "@"],
            "resolution, field ResX",
            "found the end of the file",
        ),
    ]
}
