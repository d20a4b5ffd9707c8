//! Units of length for the files and sizes people read.
//!
//! A document is in metres, glTF's unit. STL and OBJ files carry no unit at all: a slicer
//! reads an STL's numbers as millimetres, most modellers read an OBJ's as metres, so the
//! export scales to the unit the user picks, and the print check states sizes in it. This is
//! ground-floor data so that both the files (`io`) and the print check can use it.

use std::fmt;
use std::str::FromStr;

/// A unit of length. The default is the millimetre, what slicers assume for STL.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Unit {
    /// Millimetres: 1000 to the metre.
    #[default]
    Millimetre,
    /// Centimetres: 100 to the metre.
    Centimetre,
    /// Metres, the document's own unit.
    Metre,
    /// Inches: exactly 25.4 mm.
    Inch,
}

impl Unit {
    /// Every unit, smallest first, for a menu.
    pub const ALL: [Self; 4] = [Self::Millimetre, Self::Centimetre, Self::Metre, Self::Inch];

    /// How many of this unit make a metre: the factor from document lengths to this unit.
    ///
    /// ```
    /// use sketchmesh_core::unit::Unit;
    /// assert_eq!(Unit::Millimetre.per_metre(), 1000.0);
    /// assert_eq!(Unit::Inch.from_metres(0.0254), 1.0);
    /// ```
    pub fn per_metre(self) -> f64 {
        match self {
            Self::Millimetre => 1000.0,
            Self::Centimetre => 100.0,
            Self::Metre => 1.0,
            Self::Inch => 1.0 / 0.0254,
        }
    }

    /// A length in metres (a document's) in this unit.
    pub fn from_metres(self, metres: f64) -> f64 {
        // Divide for the inch so that 0.0254 m is exactly 1 in.
        match self {
            Self::Inch => metres / 0.0254,
            _ => metres * self.per_metre(),
        }
    }

    /// A length in this unit in metres.
    pub fn to_metres(self, length: f64) -> f64 {
        match self {
            Self::Inch => length * 0.0254,
            _ => length / self.per_metre(),
        }
    }

    /// The symbol people write after a number: "mm", "cm", "m" or "in".
    pub fn symbol(self) -> &'static str {
        match self {
            Self::Millimetre => "mm",
            Self::Centimetre => "cm",
            Self::Metre => "m",
            Self::Inch => "in",
        }
    }
}

impl fmt::Display for Unit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.symbol())
    }
}

/// A name that is not one of the units' symbols.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("\"{0}\" is not a unit of length; use mm, cm, m or in.")]
pub struct UnknownUnit(pub String);

impl FromStr for Unit {
    type Err = UnknownUnit;

    /// Reads a symbol as [`Unit::symbol`] writes it.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Self::ALL
            .into_iter()
            .find(|unit| unit.symbol() == s)
            .ok_or_else(|| UnknownUnit(s.to_owned()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn symbols_parse_back_and_factors_are_exact() {
        for unit in Unit::ALL {
            assert_eq!(unit.symbol().parse::<Unit>(), Ok(unit));
            assert_eq!(unit.to_string(), unit.symbol());
            assert!((unit.to_metres(unit.from_metres(0.37)) - 0.37).abs() < 1e-15);
        }
        assert_eq!(Unit::Millimetre.from_metres(0.082), 82.0);
        assert_eq!(Unit::Centimetre.from_metres(1.5), 150.0);
        assert_eq!(Unit::Inch.from_metres(0.0508), 2.0);
        assert_eq!(Unit::default(), Unit::Millimetre);
        assert_eq!(
            "ft".parse::<Unit>().unwrap_err().to_string(),
            "\"ft\" is not a unit of length; use mm, cm, m or in."
        );
    }
}
