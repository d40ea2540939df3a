// kurbo 0.7 on bench_paths.lua's path: points at k distances L i / (k - 1)
// (path.txt: "M x y C ... C ..." data, the length, k).  kurbo has no point
// at a length on a path: each segment's arclen (accuracy 1e-12 times the
// path's length, kurbo's accuracy being absolute), a walk over the segments
// and CubicBez::inv_arclen inside the one that holds the distance, as a
// user would write it.  Writes the points to argv[2] and prints ns per point.
use kurbo::{CubicBez, ParamCurve, ParamCurveArclen, Point};
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let text = std::fs::read_to_string(&args[1]).expect("cannot read path.txt");
    let lines: Vec<&str> = text.lines().collect();
    let len: f64 = lines[1].trim().parse().unwrap();
    let k: usize = lines[2].trim().parse().unwrap();
    let nums: Vec<f64> = lines[0]
        .replace('M', " ")
        .replace('C', " ")
        .split_whitespace()
        .map(|s| s.parse::<f64>().unwrap())
        .collect();
    let mut segs = Vec::new();
    let mut i = 2;
    while i + 6 <= nums.len() {
        let p0 = Point::new(nums[i - 2], nums[i - 1]);
        segs.push(CubicBez::new(
            p0,
            Point::new(nums[i], nums[i + 1]),
            Point::new(nums[i + 2], nums[i + 3]),
            Point::new(nums[i + 4], nums[i + 5]),
        ));
        i += 6;
    }
    let acc = 1e-12 * len;
    let mut pts = vec![Point::ZERO; k];
    let mut best = f64::INFINITY;
    for _ in 0..5 {
        let t0 = Instant::now();
        let cum: Vec<f64> = segs
            .iter()
            .scan(0.0, |s, c| {
                *s += c.arclen(acc);
                Some(*s)
            })
            .collect();
        let mut j = 0;
        for q in 0..k {
            let s = len * q as f64 / (k - 1) as f64;
            while j + 1 < segs.len() && cum[j] <= s {
                j += 1;
            }
            let start = if j == 0 { 0.0 } else { cum[j - 1] };
            let t = segs[j].inv_arclen((s - start).max(0.0), acc);
            pts[q] = segs[j].eval(t);
        }
        let ns = t0.elapsed().as_secs_f64() * 1e9 / k as f64;
        if ns < best {
            best = ns;
        }
    }
    let out: Vec<String> = pts.iter().map(|p| format!("{:e} {:e}", p.x, p.y)).collect();
    std::fs::write(&args[2], out.join("\n") + "\n").expect("cannot write the points");
    println!("{:.1}", best);
}
