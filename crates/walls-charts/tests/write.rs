//! Charts are written as CSV (the data, exactly), SVG and PNG; the Pareto front keeps
//! exactly the undominated points.

use walls_charts::{Chart, Mark, Series, pareto_front, write};

#[test]
fn a_chart_is_written_with_its_data() {
    let dir = tempfile::tempdir().unwrap();
    let series = vec![
        Series::new("method a", vec![(1.0, 0.5), (10.0, 0.01)], Mark::Line),
        Series::new("method b", vec![(2.0, 0.2)], Mark::Dots),
    ];
    let chart = Chart {
        name: "check".into(),
        title: "Error against cost".into(),
        x_label: "ns".into(),
        y_label: "relative error".into(),
        log_x: true,
        log_y: true,
    };
    write(dir.path(), &chart, &series).unwrap();
    let csv = std::fs::read_to_string(dir.path().join("check.csv")).unwrap();
    assert_eq!(
        csv,
        "series,x,y\nmethod a,1,0.5\nmethod a,10,0.01\nmethod b,2,0.2\n"
    );
    let svg = std::fs::read_to_string(dir.path().join("check.svg")).unwrap();
    assert!(svg.contains("Error against cost") && svg.contains("method b"));
    let png = std::fs::read(dir.path().join("check.png")).unwrap();
    assert!(png.starts_with(b"\x89PNG") && png.len() > 10_000);
}

#[test]
fn the_pareto_front_keeps_the_undominated_points() {
    let points = [
        (1.0, 5.0),
        (2.0, 3.0),
        (3.0, 4.0),
        (4.0, 1.0),
        (5.0, 1.0),
        (f64::NAN, 0.0),
    ];
    assert_eq!(
        pareto_front(&points),
        vec![(1.0, 5.0), (2.0, 3.0), (4.0, 1.0)]
    );
}
