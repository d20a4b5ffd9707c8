//! A model's material as the user sets it: base colour, roughness and metalness, glTF's
//! metallic-roughness model, so what the panel shows is what the file says.

/// The material of a model made here (see the module docs). Colours are linear.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Finish {
    /// Linear RGBA base colour; painted vertex colours multiply it (as glTF's `COLOR_0`
    /// multiplies the base colour factor).
    pub base_color: [f32; 4],
    /// 0 (mirror-smooth) to 1 (chalk).
    pub roughness: f32,
    /// 0 (dielectric) to 1 (metal).
    pub metalness: f32,
}

impl Finish {
    /// The clay every model starts in: the colour the view has always drawn models in.
    pub const CLAY: Finish = Finish {
        base_color: [0.78, 0.74, 0.68, 1.0],
        roughness: 0.6,
        metalness: 0.0,
    };

    /// This finish with every value in its range (NaN taken as 0): what an op stores, so
    /// that a session's out-of-range numbers are clamped, not refused.
    pub fn clamped(self) -> Finish {
        let unit = |x: f32| if x.is_nan() { 0.0 } else { x.clamp(0.0, 1.0) };
        Finish {
            base_color: self.base_color.map(unit),
            roughness: unit(self.roughness),
            metalness: unit(self.metalness),
        }
    }

    /// The base colour's RGB.
    pub fn rgb(&self) -> [f32; 3] {
        let [r, g, b, _] = self.base_color;
        [r, g, b]
    }
}

impl Default for Finish {
    fn default() -> Self {
        Self::CLAY
    }
}
