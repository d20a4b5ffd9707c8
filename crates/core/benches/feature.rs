//! Feature sketching (`core::feature`) on a 40,962-vertex icosphere: `FeatureEdit::new` (the
//! sketch placed and embedded, the region's system factored, its one or two solutions) and
//! one drag frame (`shape_into`: the solutions weighed, the fold check), for a ridge in the
//! 40 px band and for a bump and suggestive contours over a lasso of about 20k vertices.
//! Targets (issue 19): factor under 50 ms and a drag frame under 5 ms natively at 20k.
//! Results go in BENCHMARKS.md. Run with
//! `cargo bench -p sketchmesh-core --bench core -- '^feature_' --warm-up-time 1 --measurement-time 3`.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group};
use sketchmesh_core::feature::{FeatureEdit, FeatureKind};

use crate::common::feature;

fn bench_feature(c: &mut Criterion) {
    let mesh = feature::sphere();
    let cases = [
        ("ridge_band", FeatureKind::Ridge, false, 5.0),
        ("bump_20k", FeatureKind::Bump, true, 3.0),
        ("suggestive_20k", FeatureKind::Suggestive, true, 60.0),
    ];
    let mut group = c.benchmark_group("feature_new");
    group.sample_size(10);
    for (name, kind, with_region, _) in cases {
        let sketch = feature::sketch(with_region);
        let edit = FeatureEdit::new(&mesh, &sketch, kind).expect("the sketch is on the sphere");
        println!(
            "feature bench {name}: {} vertices, region {}, path {}",
            mesh.n_vertices(),
            edit.roi().len(),
            edit.path().len()
        );
        group.bench_with_input(BenchmarkId::from_parameter(name), &sketch, |b, sketch| {
            b.iter(|| FeatureEdit::new(black_box(&mesh), sketch, kind).expect("placed"));
        });
    }
    group.finish();

    let mut group = c.benchmark_group("feature_frame");
    for (name, kind, with_region, amount) in cases {
        let edit = FeatureEdit::new(&mesh, &feature::sketch(with_region), kind).expect("placed");
        let mut out = edit.embedded().to_vec();
        group.bench_with_input(BenchmarkId::from_parameter(name), &amount, |b, &amount| {
            b.iter(|| {
                edit.shape_into(black_box(amount), &mut out)
                    .expect("finite")
            });
        });
    }
    group.finish();
}

criterion_group!(benches, bench_feature);
