//! The region tool's profile editor (Bujans §6): a panel in the view's lower right corner
//! shows the region's cross-section in the plane across the reference curve (the plane
//! slides along the curve with the toolbar's slider); a stroke drawn in the panel over the
//! cross-section re-sketches it, and the open edit previews the region swept to match. The
//! core cuts the cross-section and turns the stroke into vertex motion
//! ([`sketchmesh_core::region_edit::ProfileChange`]); this module maps between the panel's
//! pixels and the plane.

use glam::{DVec2, DVec3};
use sketchmesh_core::document::{AreaInput, ProfileInput, RegionEditInput};
use sketchmesh_core::region_edit::{Profile, RegionEdit};

/// The panel's side as a share of the view's shorter side, and its bounds in CSS px.
const SIDE_SHARE: f64 = 0.45;
const SIDE_RANGE: (f64, f64) = (160.0, 320.0);
/// Room between the panel and the view's edges, in CSS px.
const MARGIN: f64 = 12.0;
/// The share of the panel the cross-section's larger extent fills.
const FILL: f64 = 0.8;

/// The profile editor of one region: the region, the plane's place and what was drawn.
#[derive(Debug)]
pub struct ProfileSession {
    input: RegionEditInput,
    region: RegionEdit,
    at: f64,
    profile: Result<Profile, String>,
    /// Whether the plane's `u` points left as the curves were seen: the panel then shows it
    /// mirrored, so that left in the panel is left on the model.
    mirrored: bool,
    /// The last stroke drawn in the panel, in the plane.
    stroke: Option<Vec<DVec2>>,
}

/// What the app draws for the profile editor, in CSS px of the view.
#[derive(Clone, Debug, PartialEq)]
pub struct ProfileView {
    /// The panel's top left corner.
    pub corner: DVec2,
    /// The panel's side.
    pub side: f64,
    /// The cross-section in the panel, from one side of the curve (`-u`) to the other.
    pub section: Vec<DVec2>,
    /// The stroke drawn over it, in the panel, if any.
    pub stroke: Option<Vec<DVec2>>,
    /// Where the reference curve crosses the plane, in the panel, and one panel-length of
    /// the surface normal from there: the arrow out of the surface.
    pub curve: (DVec2, DVec2),
    /// The cross-section on the model, in the world, for the view to draw too.
    pub section_in_world: Vec<DVec3>,
    /// Why there is no cross-section, if there is none.
    pub refusal: Option<String>,
}

impl ProfileSession {
    /// The profile editor of `input`'s region (`region`, on the mesh it was found on), the
    /// plane at the curve's middle.
    pub fn new(input: RegionEditInput, region: RegionEdit) -> Self {
        let mut session = ProfileSession {
            input,
            region,
            at: 0.5,
            profile: Err(String::new()),
            mirrored: false,
            stroke: None,
        };
        session.slide_to(0.5);
        session
    }

    /// The curves, as the session found them.
    pub fn curves(&self) -> &RegionEditInput {
        &self.input
    }

    /// The fall-off's levels and areas change.
    pub fn set_falloff(&mut self, levels: &[f64], areas: Vec<AreaInput>) {
        self.input.levels = Some(levels.to_vec());
        self.input.areas = areas;
    }

    /// Where the plane sits along the curve (0..1).
    pub fn at(&self) -> f64 {
        self.at
    }

    /// Moves the plane to `at` along the curve and cuts the cross-section there; a stroke
    /// drawn in the old plane is dropped.
    pub fn slide_to(&mut self, at: f64) {
        self.at = at.clamp(0.0, 1.0);
        self.stroke = None;
        self.profile = (self.region.profile(self.at)).map_err(|e| e.to_string());
        if let Ok(profile) = &self.profile {
            let camera = &self.input.camera;
            let size = DVec2::from(self.input.viewport);
            let origin = profile.frame.origin;
            let seen = |p: DVec3| camera.screen_from_world(p, size).map(|s| s.x);
            let scale = origin.length().max(1.0) * 1e-3;
            if let (Some(a), Some(b)) = (seen(origin), seen(profile.to_world(DVec2::X * scale))) {
                self.mirrored = b < a;
            }
        }
    }

    /// The op as it stands: the profile re-sketched, or the region unmoved.
    pub fn input(&self) -> RegionEditInput {
        match &self.stroke {
            Some(stroke) => RegionEditInput {
                transform: None,
                handles: None,
                profile: Some(ProfileInput {
                    at: self.at,
                    stroke: stroke.iter().map(|p| p.to_array()).collect(),
                }),
                ..self.input.clone()
            },
            None => self.input.clone(),
        }
    }

    /// Whether a stroke has re-sketched the profile.
    pub fn drawn(&self) -> bool {
        self.stroke.is_some()
    }

    /// Whether `at` (CSS px in a view of `size`) lies in the panel.
    pub fn in_panel(&self, at: DVec2, size: DVec2) -> bool {
        let (corner, side) = panel(size);
        let d = at - corner;
        d.x >= 0.0 && d.y >= 0.0 && d.x <= side && d.y <= side
    }

    /// A stroke drawn in the panel (CSS px in a view of `size`): the new cross-section.
    /// Whether it took (there is a cross-section to draw over).
    pub fn draw(&mut self, points: &[DVec2], size: DVec2) -> bool {
        let Ok(profile) = &self.profile else {
            return false;
        };
        let mapping = Mapping::new(profile, size, self.mirrored);
        self.stroke = Some(points.iter().map(|&p| mapping.to_plane(p)).collect());
        true
    }

    /// What to draw, for a view of `size`.
    pub fn view(&self, size: DVec2) -> ProfileView {
        let (corner, side) = panel(size);
        let Ok(profile) = &self.profile else {
            return ProfileView {
                corner,
                side,
                section: Vec::new(),
                stroke: None,
                curve: (corner, corner),
                section_in_world: Vec::new(),
                refusal: self.profile.clone().err(),
            };
        };
        let mapping = Mapping::new(profile, size, self.mirrored);
        let in_panel = |ps: &[DVec2]| ps.iter().map(|&p| mapping.to_panel(p)).collect();
        ProfileView {
            corner,
            side,
            section: in_panel(&profile.points),
            stroke: self.stroke.as_deref().map(in_panel),
            curve: (
                mapping.to_panel(DVec2::ZERO),
                mapping.to_panel(DVec2::new(0.0, 0.25 * side / mapping.scale)),
            ),
            section_in_world: profile
                .points
                .iter()
                .map(|&p| profile.to_world(p))
                .collect(),
            refusal: None,
        }
    }
}

/// The panel's top left corner and side, in CSS px of a view of `size`.
fn panel(size: DVec2) -> (DVec2, f64) {
    let side = (size.x.min(size.y) * SIDE_SHARE).clamp(SIDE_RANGE.0, SIDE_RANGE.1);
    (
        DVec2::new(size.x - MARGIN - side, size.y - MARGIN - side),
        side,
    )
}

/// Between the plane (`u` right, or left when mirrored; `v` up; model units) and the panel
/// (CSS px, y down): the cross-section's bounding box fitted in the middle.
struct Mapping {
    centre_plane: DVec2,
    centre_panel: DVec2,
    scale: f64,
    /// -1 when `u` runs right to left in the panel.
    across: f64,
}

impl Mapping {
    fn new(profile: &Profile, size: DVec2, mirrored: bool) -> Self {
        let (corner, side) = panel(size);
        let (lo, hi) = profile.points.iter().fold(
            (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
            |(lo, hi), &p| (lo.min(p), hi.max(p)),
        );
        let extent = (hi - lo).max_element().max(f64::MIN_POSITIVE);
        Mapping {
            centre_plane: 0.5 * (lo + hi),
            centre_panel: corner + DVec2::splat(0.5 * side),
            scale: FILL * side / extent,
            across: if mirrored { -1.0 } else { 1.0 },
        }
    }

    fn to_panel(&self, p: DVec2) -> DVec2 {
        let d = (p - self.centre_plane) * self.scale;
        self.centre_panel + DVec2::new(self.across * d.x, -d.y)
    }

    fn to_plane(&self, p: DVec2) -> DVec2 {
        let d = (p - self.centre_panel) / self.scale;
        self.centre_plane + DVec2::new(self.across * d.x, -d.y)
    }
}
