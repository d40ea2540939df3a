// kurbo 0.7's CubicBez::arclen on the curves of bench/peers/run.sh (one a
// line: kind, 8 coordinates, reference length).  kurbo's accuracy is
// absolute: it gets 1e-12 times the control polygon's length, the relative
// tolerance the other peers get.  Prints: name, median ns per random
// curve, max relative error on the random and on the adversarial curves.
use kurbo::{CubicBez, ParamCurveArclen, Point};
use std::io::{self, BufRead};
use std::time::Instant;

const REPS: usize = 8;

fn main() {
    let path = std::env::args().nth(1).expect("usage: arclen-peer-kurbo CURVES");
    let file = std::fs::File::open(path).expect("cannot open the curves file");
    let mut curves: Vec<(bool, CubicBez, f64, f64)> = Vec::new();
    for line in io::BufReader::new(file).lines() {
        let line = line.unwrap();
        let f: Vec<&str> = line.split_whitespace().collect();
        if f.len() < 10 {
            continue;
        }
        let v: Vec<f64> = f[1..10].iter().map(|s| s.parse::<f64>().unwrap()).collect();
        let p = |i: usize| Point::new(v[2 * i], v[2 * i + 1]);
        let poly = (p(1) - p(0)).hypot() + (p(2) - p(1)).hypot() + (p(3) - p(2)).hypot();
        curves.push((f[0] == "r", CubicBez::new(p(0), p(1), p(2), p(3)), poly, v[8]));
    }
    let mut times: Vec<f64> = Vec::new();
    let mut sink = 0.0;
    for (random, c, poly, _) in &curves {
        if !*random {
            continue;
        }
        let t0 = Instant::now();
        for _ in 0..REPS {
            sink += c.arclen(1e-12 * poly);
        }
        times.push(t0.elapsed().as_secs_f64() * 1e9 / REPS as f64);
    }
    times.sort_by(|a, b| a.partial_cmp(b).unwrap());
    let n = times.len();
    let median = if n % 2 == 1 { times[n / 2] } else { (times[n / 2 - 1] + times[n / 2]) / 2.0 };
    let (mut er, mut ea) = (0.0f64, 0.0f64);
    for (random, c, poly, r) in &curves {
        let l = c.arclen(1e-12 * poly);
        let mut e = if *r == 0.0 { l.abs() } else { (l - r).abs() / r };
        if e.is_nan() {
            e = f64::INFINITY;
        }
        if *random { er = er.max(e) } else { ea = ea.max(e) }
    }
    if sink == 0.12345 {
        eprintln!("{}", sink);
    }
    println!("kurbo 0.7 arclen, accuracy 1e-12 x polygon (Rust)\t{:.1}\t{:.3e}\t{:.3e}", median, er, ea);
}
