//! A synthetic trace whose every number is known (shared by the tests).
#![allow(dead_code)]

use std::fmt::Write;
use std::path::PathBuf;

/// A fresh directory for one test.
pub fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("mccl-trace-test-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Group 0 at 1 ms ticks, t = 1..=2500 ms:
/// - command 0 (LINE), 1..=1000 ms: x = 10 u², u = t/1000 s, so speed 20u UU/s, peak 20 at
///   1000 ms (x reaches 10);
/// - command 1 (ARC_CCW), 1001..=2000 ms: centre (10, 5), radius 5, θ = π/2 · (t-1000)/1000:
///   x = 10 + 5 sin θ, y = 5 − 5 cos θ, speed 5·π/2 = 7.853981634 UU/s;
/// - no command, 2001..=2500 ms, standing at (15, 5).
///
/// Group 1: z = t/100 (10 UU/s) over the whole time, command 0.
/// Events: the command starts and ends, a hold 1500..1600 ms, an error 2100..2200 ms.
pub fn write_trace(path: &std::path::Path) -> Vec<(f64, u32, [f64; 8], f64)> {
    let mut s = String::from("time_ms,group,command,status,x,y,z,u,v,w,a,b,speed\n");
    let mut rows = Vec::new();
    for k in 1..=2500u32 {
        let t = f64::from(k);
        let (cmd, x, y, sp) = if k <= 1000 {
            let u = t / 1000.0;
            (0, 10.0 * u * u, 0.0, 20.0 * u)
        } else if k <= 2000 {
            let th = std::f64::consts::FRAC_PI_2 * (t - 1000.0) / 1000.0;
            (
                1,
                10.0 + 5.0 * th.sin(),
                5.0 - 5.0 * th.cos(),
                5.0 * std::f64::consts::FRAC_PI_2,
            )
        } else {
            (-1, 15.0, 5.0, 0.0)
        };
        let status = if cmd < 0 { 0 } else { 1 };
        for (g, c, p, v) in [
            (0u32, cmd, [x, y, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0], sp),
            (
                1u32,
                0,
                [0.0, 0.0, t / 100.0, 0.0, 0.0, 0.0, 0.0, 0.0],
                10.0,
            ),
        ] {
            let _ = write!(s, "{k}.000000,{g},{c},{status}");
            for q in p {
                let _ = write!(s, ",{q:.9}");
            }
            let _ = writeln!(s, ",{v:.9}");
            // What the file holds (rounded as printed).
            let pr: Vec<f64> = p
                .iter()
                .map(|q| format!("{q:.9}").parse().unwrap())
                .collect();
            rows.push((
                t,
                g,
                pr.try_into().unwrap(),
                format!("{v:.9}").parse().unwrap(),
            ));
        }
    }
    std::fs::write(path, s).unwrap();
    let ev = "time_ms,card,group,kind,detail
0.000000,0,0,config,axis=x channel=0 ppr=500 rpm=3000 pitch=1.000000000 gear=1.000000000 max_speed=50.000000000 pulses_per_uu=500.000000000 high=50000.000000000 low=-50000.000000000 max_pulse_speed=32767 max_pulse_acc=32767
1.000000,0,0,cmd_start,index=0 type=LINE
1.000000,0,1,cmd_start,index=0 type=LINE
1000.000000,0,0,cmd_end,index=0 type=LINE end=done
1001.000000,0,0,cmd_start,index=1 type=ARC_CCW
1500.000000,0,0,hold,block_end=0
1600.000000,0,0,continue,
2000.000000,0,0,cmd_end,index=1 type=ARC_CCW end=done
2100.000000,0,0,error_set,code=0xF104
2200.000000,0,0,error_cleared,code=0xF104
";
    let ep = path.to_string_lossy().replace(".csv", ".events.csv");
    std::fs::write(ep, ev).unwrap();
    rows
}

/// The `mccl-trace` binary.
pub fn bin() -> std::process::Command {
    std::process::Command::new(env!("CARGO_BIN_EXE_mccl-trace"))
}
