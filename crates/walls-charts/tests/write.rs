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

/// The x coordinate of the SVG text that reads `label`.
fn text_x(svg: &str, label: &str) -> f64 {
    let end = svg
        .find(&format!(">\n{label}\n</text>"))
        .expect("the label is drawn");
    let start = svg[..end].rfind("<text").unwrap();
    let tag = &svg[start..end];
    let x = tag.split("x=\"").nth(1).unwrap();
    x[..x.find('"').unwrap()].parse().unwrap()
}

#[test]
fn the_legend_goes_where_it_hides_no_points() {
    let dir = tempfile::tempdir().unwrap();
    let chart = |name: &str| Chart {
        name: name.into(),
        title: "Legend".into(),
        x_label: "x".into(),
        y_label: "y".into(),
        log_x: false,
        log_y: false,
    };
    // Lines down the left side and across the bottom: the middle of the right side is
    // free, and keeps the legend.
    let low = vec![Series::new(
        "low line",
        vec![(0.0, 10.0), (0.0, 0.0), (10.0, 0.1)],
        Mark::Line,
    )];
    write(dir.path(), &chart("low"), &low).unwrap();
    let svg = std::fs::read_to_string(dir.path().join("low.svg")).unwrap();
    assert!(
        text_x(&svg, "low line") > 400.0,
        "{}",
        text_x(&svg, "low line")
    );
    // Points all over the right side: the legend moves to the left.
    let right: Vec<(f64, f64)> = (0..=20).map(|k| (10.0, f64::from(k) / 2.0)).collect();
    let crowded = vec![
        Series::new("right side", right, Mark::Dots),
        Series::new("corner", vec![(0.0, 0.0)], Mark::Dots),
    ];
    write(dir.path(), &chart("crowded"), &crowded).unwrap();
    let svg = std::fs::read_to_string(dir.path().join("crowded.svg")).unwrap();
    assert!(
        text_x(&svg, "right side") < 400.0,
        "{}",
        text_x(&svg, "right side")
    );
}
