//! The formats of a lean build: in a tracer built without its `exr` or `jpeg` feature
//! (`cargo build -p whitted --no-default-features`), `exr` and `jpeg` stand here with the
//! same calls, each refusing with the feature it needs, so that nothing above them
//! changes. `ImageFormat::from_path` refuses such a format before anything renders.

#[cfg(not(feature = "exr"))]
pub mod exr {
    //! OpenEXR without the `exr` feature: every call refuses.
    use super::super::{ExrOptions, OutputError};
    use crate::base::Transfer;
    use crate::passes::Layers;

    /// What a read says.
    const MISSING: &str = "this build reads no OpenEXR (the tracer's `exr` feature)";

    pub(in crate::output) fn encode(
        _layers: Layers,
        _options: ExrOptions,
        _meta: &[(String, String)],
        _out: &mut dyn std::io::Write,
    ) -> Result<(), OutputError> {
        Err(OutputError::NotBuilt {
            format: "exr",
            feature: "exr",
        })
    }

    pub(in crate::output) fn header_size(_read: impl std::io::Read) -> Result<(u32, u32), String> {
        Err(MISSING.into())
    }

    pub(in crate::output) type Stored = (u32, u32, Vec<[f32; 3]>, Transfer);

    pub(in crate::output) fn read_beauty(_bytes: &[u8]) -> Result<Stored, String> {
        Err(MISSING.into())
    }

    /// The string attributes of a whole EXR's header: none can be read.
    pub fn texts_if_whole(
        _file: impl std::io::Read + std::io::Seek,
        _width: u32,
        _height: u32,
    ) -> Option<Vec<(String, String)>> {
        None
    }
}

#[cfg(not(feature = "jpeg"))]
pub mod jpeg {
    //! JPEG without the `jpeg` feature: writing refuses.
    use super::super::OutputError;
    use crate::base::Frame;

    pub(in crate::output) fn encode(
        _frame: &Frame,
        _quality: u8,
        _meta: &[(String, String)],
        _out: &mut dyn std::io::Write,
    ) -> Result<(), OutputError> {
        Err(OutputError::NotBuilt {
            format: "jpg",
            feature: "jpeg",
        })
    }
}
