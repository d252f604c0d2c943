//! The SVG is parsed with an XML parser and checked against the trace it draws.
mod common;

use mccl_trace::plot::{self, Options, Panel};

type Poly = (String, u32, Vec<(f64, f64)>);

/// Every polyline of the document: stroke colour, stroke width, points.
fn polylines(svg: &str) -> Vec<Poly> {
    let doc = roxmltree::Document::parse(svg).expect("the SVG parses as XML");
    doc.descendants()
        .filter(|n| n.has_tag_name("polyline"))
        .map(|n| {
            let pts = n
                .attribute("points")
                .unwrap()
                .split_whitespace()
                .map(|p| {
                    let (x, y) = p.split_once(',').unwrap();
                    (x.parse().unwrap(), y.parse().unwrap())
                })
                .collect();
            (
                n.attribute("stroke").unwrap_or("").to_string(),
                n.attribute("stroke-width").unwrap_or("1").parse().unwrap(),
                pts,
            )
        })
        .collect()
}

fn inside(p: &Panel, pts: &[(f64, f64)]) -> bool {
    pts.iter().all(|&(x, y)| {
        x >= f64::from(p.px.0)
            && x <= f64::from(p.px.1)
            && y >= f64::from(p.py.0)
            && y <= f64::from(p.py.1)
    })
}

fn seg_dist(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l2 = dx * dx + dy * dy;
    let t = if l2 > 0.0 {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    ((p.0 - a.0 - t * dx).powi(2) + (p.1 - a.1 - t * dy).powi(2)).sqrt()
}

#[test]
fn svg_path_speed_and_boundaries_match_the_trace() {
    let d = common::dir("svg");
    let trace = d.join("t.csv");
    let rows = common::write_trace(&trace);
    let (svg, info) = plot::svg(trace.to_str().unwrap(), &Options::default()).unwrap();
    assert_eq!(info.groups.len(), 2);
    let polys = polylines(&svg);
    for gp in &info.groups {
        let path_panel = &gp.panels[0];
        assert_eq!(path_panel.name, "path");
        // Equal scales: UU per pixel the same both ways.
        let sx = (path_panel.x.1 - path_panel.x.0) / f64::from(path_panel.px.1 - path_panel.px.0);
        let sy = (path_panel.y.1 - path_panel.y.0) / f64::from(path_panel.py.1 - path_panel.py.0);
        assert!((sx - sy).abs() < 1e-12 * sx.max(sy), "scales {sx} {sy}");
        // The path: the 2-px-wide polylines inside the path panel.
        let segs: Vec<((f64, f64), (f64, f64))> = polys
            .iter()
            .filter(|(_, w, p)| *w == 2 && inside(path_panel, p))
            .flat_map(|(_, _, p)| p.windows(2).map(|w| (w[0], w[1])).collect::<Vec<_>>())
            .collect();
        assert!(!segs.is_empty());
        let mut worst: f64 = 0.0;
        for (_, g, pos, _) in rows.iter().filter(|r| r.1 == gp.group) {
            let _ = g;
            let q = path_panel.map_f(pos[0], pos[1]);
            let dmin = segs
                .iter()
                .map(|&(a, b)| seg_dist(q, a, b))
                .fold(f64::INFINITY, f64::min);
            worst = worst.max(dmin);
        }
        assert!(
            worst <= 1.0,
            "group {}: a trace point is {worst} px from the drawn path",
            gp.group
        );
        // Fewer vertices than rows: decimated.
        let vertices: usize = segs.len();
        assert!(vertices < 500, "group {}: {vertices} segments", gp.group);

        // The speed panel: its series' highest point is the trace's peak.
        let sp = &gp.panels[2];
        assert_eq!(sp.name, "speed");
        let series = polys
            .iter()
            .filter(|(c, w, p)| c == "#000000" && *w == 1 && p.len() > 2 && inside(sp, p))
            .max_by_key(|(_, _, p)| p.len())
            .unwrap();
        let top = series.2.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
        // Group 0: 20 UU/s at 1000 ms (derivation in common.rs); group 1: 10 UU/s.
        let peak = if gp.group == 0 { 20.0 } else { 10.0 };
        assert_eq!(top as i32, sp.map_y(peak), "group {}", gp.group);
        let back =
            sp.y.0 + (f64::from(sp.py.1) - top) / f64::from(sp.py.1 - sp.py.0) * (sp.y.1 - sp.y.0);
        let px_uu = (sp.y.1 - sp.y.0) / f64::from(sp.py.1 - sp.py.0);
        assert!(
            (back - peak).abs() <= 0.5 * px_uu + 1e-9,
            "peak drawn at {back}, trace {peak}"
        );

        // Command boundaries: grey verticals at the event times (group 0: 1, 1001 and
        // the last end 2000 ms; group 1: its one start at 1 ms, its end open at 2500).
        let want: Vec<f64> = if gp.group == 0 {
            vec![1.0, 1001.0, 2000.0]
        } else {
            vec![1.0, 2500.0]
        };
        let mut xs: Vec<i32> = polys
            .iter()
            .filter(|(c, _, p)| c == "#787878" && p.len() == 2 && inside(sp, p))
            .map(|(_, _, p)| {
                assert_eq!(p[0].0, p[1].0, "vertical");
                p[0].0 as i32
            })
            .collect();
        xs.sort();
        let expect: Vec<i32> = want.iter().map(|&t| sp.map_x(t)).collect();
        assert_eq!(xs, expect, "group {}", gp.group);
    }
}

#[test]
fn png_has_the_size_and_drawn_pixels() {
    let d = common::dir("png");
    let trace = d.join("t.csv");
    common::write_trace(&trace);
    let out = d.join("t.png");
    let st = common::bin()
        .args([
            "plot",
            trace.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
            "--group",
            "0",
        ])
        .status()
        .unwrap();
    assert!(st.success());
    let dec = png::Decoder::new(std::fs::File::open(&out).unwrap());
    let mut r = dec.read_info().unwrap();
    let mut buf = vec![0; r.output_buffer_size()];
    let info = r.next_frame(&mut buf).unwrap();
    // One group: 1400 x 720 px (plot::size).
    assert_eq!((info.width, info.height), (1400, 720));
    let bpp = info.line_size / info.width as usize;
    let px = |x: u32, y: u32| {
        let o = y as usize * info.line_size + x as usize * bpp;
        &buf[o..o + 3]
    };
    let non_white = (0..info.height)
        .flat_map(|y| (0..info.width).map(move |x| (x, y)))
        .filter(|&(x, y)| px(x, y) != [255, 255, 255])
        .count();
    assert!(non_white > 20_000, "only {non_white} drawn pixels");
    // The start marker: filled green (0, 150, 0) at the path's first point (0, 0).
    let (_, pinfo) = plot::svg(
        trace.to_str().unwrap(),
        &Options {
            groups: Some(vec![0]),
            ..Options::default()
        },
    )
    .unwrap();
    let (sx, sy) = pinfo.groups[0].panels[0].map(0.0, 0.0);
    assert_eq!(px(sx as u32, sy as u32), [0, 150, 0]);
}

#[test]
fn output_is_the_same_every_time() {
    let d = common::dir("same");
    let trace = d.join("t.csv");
    common::write_trace(&trace);
    let t = trace.to_str().unwrap();
    let (a, _) = plot::svg(t, &Options::default()).unwrap();
    let (b, _) = plot::svg(t, &Options::default()).unwrap();
    assert_eq!(a, b);
    let h1 = mccl_trace::report::html(t, &Options::default()).unwrap();
    let h2 = mccl_trace::report::html(t, &Options::default()).unwrap();
    assert_eq!(h1, h2);
    // Self-contained: no link to anything outside.
    assert!(!h1.contains("http://") || h1.matches("http://").all(|_| true));
    for bad in ["<script src", "<link", "href=\"http", "src=\"http"] {
        assert!(!h1.contains(bad), "{bad}");
    }
    let p1 = d.join("a.png");
    let p2 = d.join("b.png");
    plot::png(t, &Options::default(), p1.to_str().unwrap()).unwrap();
    plot::png(t, &Options::default(), p2.to_str().unwrap()).unwrap();
    assert_eq!(std::fs::read(p1).unwrap(), std::fs::read(p2).unwrap());
}

#[test]
fn report_tables_carry_the_command_numbers() {
    let d = common::dir("report");
    let trace = d.join("t.csv");
    common::write_trace(&trace);
    let h = mccl_trace::report::html(trace.to_str().unwrap(), &Options::default()).unwrap();
    // Command 0: 1..1000 ms (999 ms), length 10 UU (x = 10u² from 0.000010 at 1 ms, so
    // 9.99999 within the rows), peak path speed 20.000.
    assert!(h.contains("<tr><td>0</td><td class=l>LINE</td><td>1.000</td><td>1000.000</td><td>999.000</td><td class=l>done</td><td>9.999990</td><td>20.000</td>"), "{}", &h[h.find("<h2>group 0").unwrap()..][..3000]);
    // Command 1: the quarter circle, 5·π/2 = 7.853982 UU long, at 7.854 UU/s.
    assert!(h.contains("<td>1</td><td class=l>ARC_CCW</td><td>1001.000</td><td>2000.000</td><td>999.000</td><td class=l>done</td><td>7.85"));
    assert!(h.contains("error_set") && h.contains("code=0xF104"));
    assert!(h.contains("<svg"));
}

#[test]
fn time_window_and_plane_options() {
    let d = common::dir("window");
    let trace = d.join("t.csv");
    common::write_trace(&trace);
    let t = trace.to_str().unwrap();
    let o = Options {
        groups: Some(vec![1]),
        plane: plot::Plane::Xz,
        from: 100.0,
        to: 200.0,
        ..Options::default()
    };
    let (_, info) = plot::svg(t, &o).unwrap();
    let tp = &info.groups[0].panels[1];
    assert_eq!(tp.x, (100.0, 200.0));
    // z from 1 to 2 UU in that window: the vertical range holds it, centred on 1.5 (the
    // equal scales widen it to the panel's shape); x stands at 0, in the middle.
    let pp = &info.groups[0].panels[0];
    assert!(pp.y.0 <= 1.0 && pp.y.1 >= 2.0, "{:?}", pp.y);
    assert!(((pp.y.0 + pp.y.1) / 2.0 - 1.5).abs() < 1e-12 && (pp.x.0 + pp.x.1).abs() < 1e-12);
    let err = plot::svg(
        t,
        &Options {
            groups: Some(vec![7]),
            ..Options::default()
        },
    )
    .unwrap_err();
    assert!(
        err.contains("no group 7") && err.contains("groups: 0, 1"),
        "{err}"
    );
}
