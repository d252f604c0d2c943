//! Parsing and validation of the simulated machine's configuration.

use super::*;

/// Parses `text` as `m.toml`, expecting an error; returns the message.
fn err(text: &str) -> String {
    match SimConfig::parse(text, "m.toml") {
        Ok(cfg) => panic!("expected an error, parsed {cfg:?}"),
        Err(e) => e,
    }
}

/// Asserts that `msg` starts with `m.toml:<line>: ` and contains every one of `parts`.
fn assert_msg(msg: &str, line: usize, parts: &[&str]) {
    let prefix = format!("m.toml:{line}: ");
    assert!(
        msg.starts_with(&prefix),
        "{msg:?} should start with {prefix:?}"
    );
    for p in parts {
        assert!(msg.contains(p), "{msg:?} should contain {p:?}");
    }
}

/// The lines of `text` that are a single-`#` commented example, uncommented.
fn uncomment(text: &str) -> String {
    text.lines()
        .filter_map(|l| {
            if l == "#" {
                Some("")
            } else {
                l.strip_prefix("# ")
            }
        })
        .map(|l| format!("{l}\n"))
        .collect()
}

#[test]
fn embedded_default_is_the_ideal_machine() {
    let cfg = SimConfig::parse(DEFAULT_TOML, DEFAULT_NAME).expect("default parses");
    assert_eq!(cfg, SimConfig::default());
    assert_eq!(SimConfig::from_env_value(None), Ok(SimConfig::default()));
    assert_eq!(
        SimConfig::from_env_value(Some(OsStr::new(""))),
        Ok(SimConfig::default())
    );
    let ch = cfg.channel(0, 0);
    assert!(!ch.home_active(0.0) && !ch.limit_plus_active(1e9) && !ch.limit_minus_active(-1e9));
    assert_eq!(ch.plant, Plant::Ideal);
    assert_eq!(ch.adc, None);
    assert!(!cfg.card(0).emergency_stop);
    assert_eq!(cfg.card(0).rio_slave(0, 0), None);
}

/// The example commented into the default (every key) parses to exactly this.
#[test]
fn default_example_parses_to_expected_structs() {
    let text = uncomment(DEFAULT_TOML);
    let cfg = SimConfig::parse(&text, "example.toml").expect("example parses");
    let mut want = SimConfig::default();
    want.cards[0].mc3b_port = Some("/dev/pts/5".to_owned());
    want.cards[0].channels[0] = ChannelSim {
        home: Some((-1.0, 1.0)),
        home_nc: false,
        limit_plus: Some(100.0),
        limit_minus: Some(-100.0),
        index_spacing: Some(2000),
        index_phase: 0,
        plant: Plant::Lag { tau_s: 0.02 },
        adc: Some(AdcSource::Dac(0)),
        mc3b_limit_bits: Some([0, 1]),
    };
    want.cards[0].channels[1].adc = Some(AdcSource::Volts(2.5));
    want.cards[0].rio = vec![
        RioSlaveSim {
            set: 0,
            slave: 3,
            inputs: [1, 0, 0, 0xFFFF],
            loopback: false,
        },
        RioSlaveSim {
            set: 1,
            slave: 0,
            inputs: [0; 4],
            loopback: true,
        },
    ];
    assert_eq!(cfg, want);
    assert_eq!(cfg.card(0).rio_slave(1, 0).map(|r| r.loopback), Some(true));
}

/// The example of docs/simulated-machine.md is valid.
#[test]
fn docs_example_parses() {
    let doc = include_str!("../../../../../docs/simulated-machine.md");
    let section = doc
        .split("# The simulated machine: `MCCL_SIM`")
        .nth(1)
        .expect("docs/simulated-machine.md has the MCCL_SIM section");
    let block = section
        .split("```toml\n")
        .nth(1)
        .and_then(|b| b.split("```").next())
        .expect("the section has a toml block");
    let cfg = SimConfig::parse(block, "machine.toml").expect("the docs example parses");
    assert_eq!(cfg.channel(0, 0).index_phase, 500);
    assert_eq!(cfg.channel(0, 0).plant, Plant::Lag { tau_s: 0.02 });
    assert_eq!(
        cfg.card(0).rio_slave(0, 3).map(|r| r.inputs),
        Some([1, 0, 0, 0])
    );
    // The two messages the docs show are the ones the library gives.
    let shown: Vec<&str> = section
        .lines()
        .map(str::trim)
        .filter(|l| l.starts_with("machine.toml:"))
        .collect();
    assert_eq!(shown.len(), 2);
    let bad_limit = block.replace("limit_minus = -100.0", "limit_minus = 100.0");
    let e = SimConfig::parse(&bad_limit, "machine.toml").expect_err("bad limit");
    assert_eq!(e, shown[0]);
    let typo = block.replace("limit_plus = 100.0", "lmit_plus = 100.0");
    let e = SimConfig::parse(&typo, "machine.toml").expect_err("typo");
    let cut = shown[1].trim_end_matches("...)");
    assert!(e.starts_with(cut), "{e:?} should start with {cut:?}");
}

#[test]
fn full_example_with_every_form() {
    let text = r#"
[[card]]
index = 2
emergency_stop = true

[[card.channel]]
index = 7
home = [5, 6.5]          # integers are numbers too
limit_minus = -0.5
index_phase = 123        # no spacing: reduced modulo the default later
plant = { lag_ms = 1e4 }
adc = -10

[[card.rio]]
set = 1
slave = 31
inputs = [0b1010]

[[card]]
index = 11
"#;
    let cfg = SimConfig::parse(text, "m.toml").expect("parses");
    let card = cfg.card(2);
    assert!(card.emergency_stop);
    assert_eq!(card.mc3b_port, None);
    let ch = cfg.channel(2, 7);
    assert_eq!(ch.home, Some((5.0, 6.5)));
    assert_eq!((ch.limit_plus, ch.limit_minus), (None, Some(-0.5)));
    assert_eq!((ch.index_spacing, ch.index_phase), (None, 123));
    assert_eq!(ch.plant, Plant::Lag { tau_s: 10.0 });
    assert_eq!(ch.adc, Some(AdcSource::Volts(-10.0)));
    assert_eq!(
        card.rio,
        vec![RioSlaveSim {
            set: 1,
            slave: 31,
            inputs: [10, 0, 0, 0],
            loopback: false
        }]
    );
    assert_eq!(cfg.card(11), &CardSim::default());
    assert_eq!(cfg.channel(2, 0), &ChannelSim::default());
    // Out of range reads as ideal rather than panicking.
    assert_eq!(cfg.card(12), &CardSim::default());
    assert_eq!(cfg.channel(2, 8), &ChannelSim::default());
}

#[test]
fn inline_tables_are_accepted_and_located() {
    let ok = "card = [{ index = 1, channel = [{ index = 3, limit_plus = 9 }] }]\n";
    let cfg = SimConfig::parse(ok, "m.toml").expect("parses");
    assert_eq!(cfg.channel(1, 3).limit_plus, Some(9.0));
    let bad = "card = [\n  { index = 1, channel = [\n    { index = 3, limit_plus = nan } ] } ]\n";
    assert_msg(&err(bad), 3, &["card[1].channel[3].limit_plus", "finite"]);
    let unknown = "card = [{ index = 1, channel = [{ index = 3, lmit = 1 }] }]\n";
    assert_msg(
        &err(unknown),
        1,
        &["unknown key \"lmit\" in card[1].channel[3]"],
    );
}

#[test]
fn sensor_helpers() {
    let ch = ChannelSim {
        home: Some((-1.0, 1.0)),
        limit_plus: Some(100.0),
        limit_minus: Some(-100.0),
        index_phase: 2500,
        ..ChannelSim::default()
    };
    assert!(ch.home_active(-1.0) && ch.home_active(1.0) && !ch.home_active(1.001));
    assert!(ch.limit_plus_active(100.0) && !ch.limit_plus_active(99.9));
    assert!(ch.limit_minus_active(-100.0) && !ch.limit_minus_active(-99.9));
    assert_eq!(
        ch.index_spacing_or(500),
        500,
        "one index per motor turn: dwPPR pulses"
    );
    assert_eq!(ch.index_phase_in(2000), 500);
    assert_eq!(ch.index_spacing_or(0), 1);
    assert_eq!(ch.index_phase_in(0), 0);
    let set = ChannelSim {
        index_spacing: Some(7),
        ..ChannelSim::default()
    };
    assert_eq!(set.index_spacing_or(500), 7);
    assert_eq!(ChannelSim::default().index_spacing_or(u32::MAX), u32::MAX);
}

// ---- one test per error kind: the line and the key are in the message ----

#[test]
fn unknown_key() {
    let text = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\nlmit_plus = 100.0\n";
    assert_msg(
        &err(text),
        5,
        &[
            "unknown key \"lmit_plus\" in card[0].channel[0]",
            "limit_plus",
        ],
    );
    assert_msg(
        &err("\n\ncards = 1\n"),
        3,
        &["unknown key \"cards\" at the top level"],
    );
    assert_msg(
        &err("[[card]]\nindex = 4\nemergncy_stop = true\n"),
        3,
        &["unknown key \"emergncy_stop\" in card[4]"],
    );
    assert_msg(
        &err("[[card]]\nindex = 0\n[[card.rio]]\nset = 0\nslave = 2\nloopbak = true\n"),
        6,
        &["unknown key \"loopbak\" in card[0].rio[0,2]"],
    );
    assert_msg(
        &err("[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\nplant = { lag = 3 }\n"),
        5,
        &["card[0].channel[0].plant", "unknown key \"lag\""],
    );
}

#[test]
fn wrong_type() {
    let text = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 1\nlimit_plus = \"far\"\n";
    assert_msg(
        &err(text),
        5,
        &[
            "card[0].channel[1].limit_plus",
            "wrong type",
            "\"far\"",
            "a number",
        ],
    );
    assert_msg(
        &err("[[card]]\nindex = 0\nemergency_stop = 1\n"),
        3,
        &["card[0].emergency_stop", "wrong type", "true or false"],
    );
    assert_msg(
        &err("[[card]]\nindex = 1.5\n"),
        2,
        &["card[?].index", "wrong type", "an integer"],
    );
    assert_msg(
        &err("[card]\nindex = 0\n"),
        1,
        &[
            "card",
            "wrong type: found a table, expected an array",
            "[[card]]",
        ],
    );
    assert_msg(
        &err("[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\nhome = 1.0\n"),
        5,
        &["card[0].channel[0].home", "wrong type", "an array"],
    );
    assert_msg(
        &err("[[card]]\nindex = 0\n[card.channel]\nindex = 0\n"),
        3,
        &["card[0].channel", "[[card.channel]]"],
    );
}

#[test]
fn missing_index() {
    assert_msg(
        &err("[[card]]\nemergency_stop = true\n"),
        1,
        &["card[?]", "missing required key \"index\""],
    );
    assert_msg(
        &err("[[card]]\nindex = 0\n\n[[card.rio]]\nslave = 1\n"),
        4,
        &["card[0].rio[?,1]", "missing required key \"set\""],
    );
}

#[test]
fn toml_syntax_errors_name_the_line() {
    let text = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\nlimit_plus = 1\nlimit_plus = 2\n";
    assert_msg(&err(text), 6, &["duplicate key", "limit_plus"]);
    assert_msg(&err("[[card]]\nindex = = 0\n"), 2, &["TOML syntax error"]);
}

#[test]
fn duplicate_card_index() {
    let text = "[[card]]\nindex = 3\n\n[[card]]\nindex = 3\n";
    assert_msg(
        &err(text),
        5,
        &[
            "card[3].index",
            "card 3 is configured twice (first at line 2)",
        ],
    );
}

#[test]
fn duplicate_channel_index() {
    let text = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 2\n[[card.channel]]\nindex = 2\n";
    assert_msg(
        &err(text),
        6,
        &[
            "card[0].channel[2].index",
            "channel 2 is configured twice",
            "line 4",
        ],
    );
    // The same channel index on two cards is fine.
    let ok = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 2\n\
              [[card]]\nindex = 1\n[[card.channel]]\nindex = 2\n";
    assert!(SimConfig::parse(ok, "m.toml").is_ok());
}

#[test]
fn index_out_of_range() {
    assert_msg(
        &err("[[card]]\nindex = 12\n"),
        2,
        &["card[12].index", "must be 0..11, not 12"],
    );
    assert_msg(
        &err("[[card]]\nindex = -1\n"),
        2,
        &["card[-1].index", "must be 0..11"],
    );
    assert_msg(
        &err("[[card]]\nindex = 0\n[[card.channel]]\nindex = 8\n"),
        4,
        &["card[0].channel[8].index", "must be 0..7, not 8"],
    );
}

#[test]
fn home_from_not_below_to() {
    let text = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\nhome = [1.0, 1.0]\n";
    assert_msg(
        &err(text),
        5,
        &["card[0].channel[0].home", "from must be less than to"],
    );
    let three = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\nhome = [1, 2, 3]\n";
    assert_msg(&err(three), 5, &["card[0].channel[0].home", "two numbers"]);
}

#[test]
fn limit_minus_not_below_limit_plus() {
    let text = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 2\n\
                limit_plus = 100.0\n\nlimit_minus = 100\n";
    assert_msg(
        &err(text),
        7,
        &["card[0].channel[2].limit_minus: must be less than limit_plus (100)"],
    );
}

#[test]
fn index_spacing_zero() {
    let text = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\nindex_spacing = 0\n";
    assert_msg(
        &err(text),
        5,
        &["card[0].channel[0].index_spacing", "must be 1.."],
    );
    let big = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\nindex_spacing = 0x1_0000_0000\n";
    assert_msg(
        &err(big),
        5,
        &["card[0].channel[0].index_spacing", "4294967296"],
    );
}

#[test]
fn index_phase_not_below_spacing() {
    let text = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\n\
                index_spacing = 2000\nindex_phase = 2000\n";
    assert_msg(
        &err(text),
        6,
        &[
            "card[0].channel[0].index_phase",
            "less than index_spacing (2000)",
        ],
    );
    let neg = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\nindex_phase = -1\n";
    assert_msg(&err(neg), 5, &["card[0].channel[0].index_phase", "not -1"]);
}

#[test]
fn lag_out_of_range() {
    for (lag, shown) in [("0", "not 0"), ("-5", "not -5"), ("10000.5", "not 10000.5")] {
        let text = format!(
            "[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\nplant = {{ lag_ms = {lag} }}\n"
        );
        assert_msg(
            &err(&text),
            5,
            &[
                "card[0].channel[0].plant",
                "lag_ms must be 0 < lag_ms <= 10000",
                shown,
            ],
        );
    }
    let name = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\nplant = \"lag\"\n";
    assert_msg(
        &err(name),
        5,
        &["card[0].channel[0].plant", "\"ideal\"", "not \"lag\""],
    );
    let missing = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\nplant = {}\n";
    assert_msg(&err(missing), 5, &["plant", "lag_ms is missing"]);
}

#[test]
fn nan_and_inf() {
    let text = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 1\nlimit_plus = nan\n";
    assert_msg(
        &err(text),
        5,
        &["card[0].channel[1].limit_plus", "finite", "NaN"],
    );
    let inf = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 1\nhome = [-inf, 0]\n";
    assert_msg(&err(inf), 5, &["card[0].channel[1].home", "finite", "-inf"]);
    let lag = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 1\nplant = { lag_ms = inf }\n";
    assert_msg(&err(lag), 5, &["plant", "not inf"]);
    let adc = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 1\nadc = nan\n";
    assert_msg(&err(adc), 5, &["card[0].channel[1].adc", "not NaN"]);
}

#[test]
fn bad_adc_source() {
    for (v, shown) in [
        ("\"dac8\"", "not \"dac8\""),
        ("\"DAC0\"", "not \"DAC0\""),
        ("\"dac\"", "not \"dac\""),
        ("\"dac01\"", "not \"dac01\""),
        ("10.5", "not 10.5"),
        ("true", "not true"),
        ("[1]", "not array"),
    ] {
        let text = format!("[[card]]\nindex = 5\n[[card.channel]]\nindex = 6\nadc = {v}\n");
        assert_msg(
            &err(&text),
            5,
            &["card[5].channel[6].adc", "\"dac0\"..\"dac7\"", shown],
        );
    }
    let ok = "[[card]]\nindex = 5\n[[card.channel]]\nindex = 6\nadc = \"dac7\"\n";
    let cfg = SimConfig::parse(ok, "m.toml").expect("dac7 is fine");
    assert_eq!(cfg.channel(5, 6).adc, Some(AdcSource::Dac(7)));
}

#[test]
fn bad_rio() {
    let set = "[[card]]\nindex = 0\n[[card.rio]]\nset = 2\nslave = 0\n";
    assert_msg(
        &err(set),
        4,
        &["card[0].rio[2,0].set", "must be 0..1, not 2"],
    );
    let slave = "[[card]]\nindex = 0\n[[card.rio]]\nset = 0\nslave = 32\n";
    assert_msg(
        &err(slave),
        5,
        &["card[0].rio[0,32].slave", "must be 0..31, not 32"],
    );
    let ports = "[[card]]\nindex = 0\n[[card.rio]]\nset = 0\nslave = 0\ninputs = [1, 2, 3, 4, 5]\n";
    assert_msg(
        &err(ports),
        6,
        &["card[0].rio[0,0].inputs", "at most 4 ports", "not 5"],
    );
    let word = "[[card]]\nindex = 0\n[[card.rio]]\nset = 0\nslave = 0\ninputs = [0x10000]\n";
    assert_msg(
        &err(word),
        6,
        &["card[0].rio[0,0].inputs", "0..65535, not 65536"],
    );
    let both = "[[card]]\nindex = 0\n[[card.rio]]\nset = 0\nslave = 0\n\
                inputs = [1]\nloopback = true\n";
    assert_msg(&err(both), 6, &["card[0].rio[0,0].inputs", "looped-back"]);
    let twice = "[[card]]\nindex = 0\n[[card.rio]]\nset = 1\nslave = 4\n\
                 [[card.rio]]\nset = 1\nslave = 4\n";
    assert_msg(
        &err(twice),
        8,
        &[
            "card[0].rio[1,4].slave",
            "set 1 slave 4 is configured twice",
            "line 5",
        ],
    );
}

#[test]
fn home_contact() {
    let ok = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 1\nhome_contact = \"nc\"\n";
    let cfg = SimConfig::parse(ok, "t.toml").expect("nc parses");
    assert!(cfg.channel(0, 1).home_nc && !cfg.channel(0, 0).home_nc);
    let text = ok.replace("\"nc\"", "\"closed\"");
    assert_msg(
        &err(&text),
        5,
        &["card[0].channel[1].home_contact", "\"no\"", "\"closed\""],
    );
}

#[test]
fn mc3b_limit_bits() {
    let ok = "[[card]]\nindex = 0\nmc3b_port = \"/dev/x\"\n[[card.channel]]\nindex = 2\nmc3b_limit_bits = [5, -1]\n";
    let cfg = SimConfig::parse(ok, "t.toml").expect("parses");
    assert_eq!(cfg.channel(0, 2).mc3b_limit_bits, Some([5, -1]));
    let e = err(&ok.replace("[5, -1]", "[6, 0]"));
    assert_msg(&e, 6, &["card[0].channel[2].mc3b_limit_bits", "0..5"]);
    let e = err(&ok.replace("index = 2", "index = 3"));
    assert_msg(&e, 6, &["mc3b_limit_bits", "channels 0..2"]);
    let e = err(&ok.replace("mc3b_port = \"/dev/x\"\n", ""));
    assert_msg(&e, 5, &["mc3b_limit_bits", "mc3b_port"]);
}

#[test]
fn empty_mc3b_port() {
    let text = "[[card]]\nindex = 0\nmc3b_port = \"\"\n";
    assert_msg(&err(text), 3, &["card[0].mc3b_port", "serial port"]);
}

#[test]
fn every_problem_is_reported_in_file_order() {
    let text = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 9\n\
                [[card.channel]]\nindex = 1\nindex_spacing = 0\n";
    let msg = err(text);
    let lines: Vec<&str> = msg.lines().collect();
    assert_eq!(lines.len(), 2, "{msg}");
    assert_msg(lines[0], 4, &["card[0].channel[9].index"]);
    assert_msg(lines[1], 7, &["card[0].channel[1].index_spacing"]);
}

#[test]
fn unreadable_path_is_named() {
    let path = std::env::temp_dir().join(format!("mccl-sim-missing-{}.toml", std::process::id()));
    let e = SimConfig::from_env_value(Some(path.as_os_str())).expect_err("missing file");
    assert!(e.contains("MCCL_SIM="), "{e}");
    assert!(e.contains(&path.display().to_string()), "{e}");
    assert!(e.contains("cannot read"), "{e}");
    // A directory is not readable as a file either.
    let dir = std::env::temp_dir();
    let e = SimConfig::from_env_value(Some(dir.as_os_str())).expect_err("a directory");
    assert!(e.contains(&dir.display().to_string()), "{e}");
}

#[test]
fn file_errors_name_the_path_and_line() {
    let dir = std::env::temp_dir();
    let path = dir.join(format!("mccl-sim-test-{}.toml", std::process::id()));
    std::fs::write(
        &path,
        "[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\nlimit_plus = -1\nlimit_minus = 1\n",
    )
    .expect("write temp file");
    let e = SimConfig::from_file(&path).expect_err("bad limits");
    let name = path.display().to_string();
    assert!(
        e.starts_with(&format!("{name}:6: card[0].channel[0].limit_minus")),
        "{e}"
    );
    std::fs::write(&path, b"\xff\xfe").expect("write temp file");
    let e = SimConfig::from_file(&path).expect_err("not UTF-8");
    assert!(e.contains(&name) && e.contains("UTF-8"), "{e}");
    std::fs::write(&path, "[[card]]\nindex = 1\nemergency_stop = true\n").expect("write");
    let cfg = SimConfig::from_env_value(Some(path.as_os_str())).expect("good file");
    assert!(cfg.card(1).emergency_stop);
    let _ = std::fs::remove_file(&path);
}
