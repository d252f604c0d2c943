//! What the program configures before (and while) the card runs: mechanism, encoder and
//! go-home parameters per channel, the group table and the system maximum feed speed
//! (user manual §2.4–2.5). Every setter validates first and changes nothing on error.

use crate::error::{McclError, McclResult};
use crate::vendor::consts as c;
use crate::vendor::{SYS_ENCODER_CONFIG, SYS_HOME_CONFIG, SYS_MAC_PARAM};

pub mod legacy;

/// Cards the library accepts (`MAX_CARD_NUM`).
pub const CARDS: usize = c::MAX_CARD_NUM as usize;
/// Channels (axes) per card and axes per group.
pub const AXES: usize = c::MAX_AXIS_NUM as usize;
/// Group slots (`MAX_GROUP_NUM`).
pub const GROUPS: usize = c::MAX_GROUP_NUM as usize;
/// Largest command queue a group may ask for (memory guard; the vendor default is 10000).
pub const MAX_QUEUE_SIZE: usize = 1_000_000;

/// Mechanism parameters per card and channel.
pub type MacTable = [[SYS_MAC_PARAM; AXES]; CARDS];

/// A validated card index.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct CardIx(pub usize);

/// A validated channel index on a card.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct ChannelIx(pub usize);

impl CardIx {
    /// Checks a card index against `MAX_CARD_NUM` (`PARAMETER_ERR` otherwise).
    pub fn new(card: impl TryInto<usize>) -> McclResult<CardIx> {
        match card.try_into() {
            Ok(c) if c < CARDS => Ok(CardIx(c)),
            _ => Err(McclError::Parameter),
        }
    }
}

impl ChannelIx {
    /// Checks a channel index against the 8 channels of a card (`PARAMETER_ERR` otherwise).
    pub fn new(ch: impl TryInto<usize>) -> McclResult<ChannelIx> {
        match ch.try_into() {
            Ok(c) if c < AXES => Ok(ChannelIx(c)),
            _ => Err(McclError::Parameter),
        }
    }
}

/// The mechanism parameters used until the program sets its own: the example of user
/// manual §2.4.1 (500 pulses per turn, 3000 rpm, pitch 1, gear ratio 1, ±50000 UU,
/// pulse/direction output, limit switches unused).
pub fn default_mac_param() -> SYS_MAC_PARAM {
    SYS_MAC_PARAM {
        wPosToEncoderDir: 0,
        wRPM: 3000,
        dwPPR: 500,
        dfPitch: 1.0,
        dfGearRatio: 1.0,
        dfHighLimit: 50000.0,
        dfLowLimit: -50000.0,
        dfHighLimitOffset: 0.0,
        dfLowLimitOffset: 0.0,
        wPulseMode: c::DDA_FMT_PD,
        wPulseWidth: 100,
        wCommandMode: c::OCM_PULSE,
        wPaddle: 0,
        wOverTravelUpSensorMode: c::SL_UNUSED,
        wOverTravelDownSensorMode: c::SL_UNUSED,
    }
}

/// The encoder configuration used until the program sets its own: the example of user
/// manual §2.4.2 (A/B phase, no inversion, no swap, x4).
pub fn default_encoder_config() -> SYS_ENCODER_CONFIG {
    SYS_ENCODER_CONFIG {
        wType: c::ENC_TYPE_AB,
        wAInverse: 0,
        wBInverse: 0,
        wCInverse: 0,
        wABSwap: 0,
        wInputRate: 4,
        wPaddle: [0; 2],
    }
}

/// The go-home configuration used until the program sets its own, as the vendor's
/// library reads right after init: mode 3, direction 0, normally open, index count 0,
/// 300 ms ramps, 1 / 1 UU/s, no offset.
pub fn default_home_config() -> SYS_HOME_CONFIG {
    SYS_HOME_CONFIG {
        wMode: 3,
        wDirection: 0,
        wSensorMode: c::SL_NORMAL_OPEN,
        wPaddel0: 0,
        nIndexCount: 0,
        nPaddel1: 0,
        dfAccTime: 300.0,
        dfDecTime: 300.0,
        dfHighSpeed: 1.0,
        dfLowSpeed: 1.0,
        dfOffset: 0.0,
    }
}

/// The documented ranges of the numbers a program passes (docs/compatibility.md
/// "Ranges"), one check per kind of quantity. A value whose consequence the library
/// cannot represent — a count beyond its counter, a time longer than it can count, a
/// factor that overflows — is `PARAMETER_ERR`, and the call changes nothing.
pub mod range {
    use crate::error::{McclError, McclResult};

    /// Longest time, ms: 2^32 − 1 (49.7 days). The vendor's own time arguments are
    /// DWORD ms (`MCC_DelayMotion`, `MCC_TimeDelay`), and a command's own time, counted
    /// in `f64` seconds, still resolves 1 ns at 2^32 ms (its step there is 2^-30 s).
    pub const MAX_TIME_MS: f64 = 4_294_967_295.0;
    /// [`MAX_TIME_MS`] in seconds: the longest a queued command may last.
    pub const MAX_TIME_S: f64 = MAX_TIME_MS / 1000.0;
    /// Largest pulse count of a channel (and |position| × pulses per UU of an axis):
    /// 10^15. Pulses are computed in `f64`, which holds every integer only up to
    /// 2^53 ≈ 9.007e15; 10^15 is the round number below (31 years at 1 MHz).
    pub const MAX_PULSES: f64 = 1e15;
    /// Slowest speed, UU/s: a unit takes 11.6 days, a quarter of the longest time.
    pub const MIN_SPEED: f64 = 1e-6;
    /// Fastest speed, UU/s: the planner squares speeds and divides them by times;
    /// 10^9 keeps that far inside `f64` and far above any machine.
    pub const MAX_SPEED: f64 = 1e9;
    /// Fewest pulses per UU (dwPPR × dfGearRatio / dfPitch): one pulse per 10^6 UU.
    pub const MIN_FACTOR: f64 = 1e-6;
    /// Most pulses per UU: 10^9 (a work zone of ±10^6 UU still fits [`MAX_PULSES`]).
    pub const MAX_FACTOR: f64 = 1e9;
    /// Smallest `MCC_SetENCGearRate`: a thousand motor pulses per count.
    pub const MIN_ENC_GEAR: f64 = 1e-3;
    /// Largest `MCC_SetENCGearRate`: a thousand counts per motor pulse.
    pub const MAX_ENC_GEAR: f64 = 1e3;
    /// Largest |encoder count|: [`MAX_PULSES`] × [`MAX_ENC_GEAR`] = 10^18, every count
    /// a motor in range can make; a count set plus one counted stays within `i64`
    /// (9.2e18).
    pub const MAX_ENC_COUNT: i64 = 1_000_000_000_000_000_000;
    /// Smallest percentage (override, PtP and jog ratio): 0.01 %. At that rate a 1 ms
    /// tick still advances a command's own time by 10^-7 s, a hundred times its
    /// resolution at [`MAX_TIME_S`], so a slowed command always ends.
    pub const MIN_PERCENT: f64 = 0.01;

    fn within(x: f64, lo: f64, hi: f64) -> McclResult<f64> {
        if x.is_finite() && lo <= x && x <= hi {
            Ok(x)
        } else {
            Err(McclError::Parameter)
        }
    }

    /// A time in ms: 0..=[`MAX_TIME_MS`].
    pub fn time_ms(t: f64) -> McclResult<f64> {
        within(t, 0.0, MAX_TIME_MS)
    }

    /// A planned duration in seconds: at most [`MAX_TIME_S`].
    pub fn duration_s(t: f64) -> McclResult<f64> {
        within(t, 0.0, MAX_TIME_S)
    }

    /// A speed in UU/s: [`MIN_SPEED`]..=[`MAX_SPEED`].
    pub fn speed(v: f64) -> McclResult<f64> {
        within(v, MIN_SPEED, MAX_SPEED)
    }

    /// A percentage: [`MIN_PERCENT`]..=`max`.
    pub fn percent(p: f64, max: f64) -> McclResult<f64> {
        within(p, MIN_PERCENT, max)
    }

    /// Pulses per UU (either sign): |f| in [`MIN_FACTOR`]..=[`MAX_FACTOR`].
    pub fn factor(f: f64) -> McclResult<f64> {
        within(f.abs(), MIN_FACTOR, MAX_FACTOR).map(|_| f)
    }

    /// An encoder gear rate: [`MIN_ENC_GEAR`]..=[`MAX_ENC_GEAR`].
    pub fn enc_gear(r: f64) -> McclResult<f64> {
        within(r, MIN_ENC_GEAR, MAX_ENC_GEAR)
    }

    /// A position (or distance) in UU of an axis with `factor` pulses per UU: finite,
    /// and |x| × |factor| <= [`MAX_PULSES`].
    pub fn position(x: f64, factor: f64) -> McclResult<f64> {
        if x.is_finite() && x.abs() * factor.abs() <= MAX_PULSES {
            Ok(x)
        } else {
            Err(McclError::Parameter)
        }
    }

    /// An encoder count (set or compared): |n| <= [`MAX_ENC_COUNT`].
    pub fn enc_count(n: i64) -> McclResult<i64> {
        if n.unsigned_abs() <= MAX_ENC_COUNT.unsigned_abs() {
            Ok(n)
        } else {
            Err(McclError::Parameter)
        }
    }
}

fn check(ok: bool) -> McclResult<()> {
    if ok {
        Ok(())
    } else {
        Err(McclError::Parameter)
    }
}

/// Validates mechanism parameters (§2.4.1) as the vendor's library does: PPR > 0, pitch
/// and gear ratio finite and > 0 with pulses per UU in [`range::factor`], the maximum
/// safe speed at most [`range::MAX_SPEED`], limits and limit offsets positions in
/// [`range::position`] with the high limit >= 0 >= the low limit, pulse mode
/// `DDA_FMT_*`, command mode `OCM_*`, sensor modes `SL_*`, pulse width and RPM > 0. Any
/// direction is taken (nonzero reverses, measured), and any paddle value.
pub fn validate_mac_param(p: &SYS_MAC_PARAM) -> McclResult<()> {
    check(p.dwPPR > 0)?;
    check(p.dfPitch.is_finite() && p.dfPitch > 0.0)?;
    check(p.dfGearRatio.is_finite() && p.dfGearRatio > 0.0)?;
    let f = range::factor(conv_factor(p))?;
    let safe = f64::from(p.wRPM) / 60.0 * p.dfPitch / p.dfGearRatio;
    check(safe <= range::MAX_SPEED)?;
    for x in [
        p.dfHighLimit,
        p.dfLowLimit,
        p.dfHighLimitOffset,
        p.dfLowLimitOffset,
    ] {
        range::position(x, f)?;
    }
    check(p.dfLowLimit <= 0.0 && p.dfHighLimit >= 0.0)?;
    check(p.wPulseMode <= c::DDA_FMT_AB)?;
    // A pulse of no width: the vendor's library refuses it.
    check(p.wPulseWidth > 0)?;
    check(p.wRPM > 0)?;
    check(p.wCommandMode <= c::OCM_SWCLOSELOOP)?;
    check(p.wOverTravelUpSensorMode <= c::SL_UNUSED)?;
    check(p.wOverTravelDownSensorMode <= c::SL_UNUSED)?;
    Ok(())
}

/// Validates an encoder configuration (§2.4.2): type `ENC_TYPE_*`, flags 0/1, input rate
/// 1, 2 or 4 as the manual writes it (3, `ENC_RATE_X4` of IMCDefine.h, also means x4).
pub fn validate_encoder_config(e: &SYS_ENCODER_CONFIG) -> McclResult<()> {
    check(e.wType <= c::ENC_TYPE_AB)?;
    check(e.wAInverse <= 1 && e.wBInverse <= 1 && e.wCInverse <= 1 && e.wABSwap <= 1)?;
    check(matches!(e.wInputRate, 1..=4))?;
    Ok(())
}

/// Counts per encoder cycle for a validated `wInputRate` (1, 2, or 4 for both 3 and 4).
pub fn encoder_multiplier(input_rate: u16) -> u32 {
    match input_rate {
        1 => 1,
        2 => 2,
        _ => 4,
    }
}

/// The go-home modes `MCC_SetHomeConfig` takes: 0..=19, as the vendor's library takes
/// them. The manual describes 3..=16 ([`HOME_MODES_RUN`]); the others are kept and read
/// back, and `MCC_Home` refuses to run them.
pub const HOME_MODES_SET: std::ops::RangeInclusive<u16> = 0..=19;

/// The go-home modes the manual describes (§2.8.1) and `MCC_Home` runs.
pub const HOME_MODES_RUN: std::ops::RangeInclusive<u16> = 3..=16;

/// Validates go-home parameters (§2.4.3) for a channel with mechanism parameters `mac`,
/// as the vendor's library checks them: mode in [`HOME_MODES_SET`], direction 0/1,
/// sensor mode normally open or closed (0/1), index count >= 0, acc/dec times > 0 within
/// [`range::time_ms`], speeds in [`range::speed`], the offset a position of the channel
/// ([`range::position`]).
pub fn validate_home_config(h: &SYS_HOME_CONFIG, mac: &SYS_MAC_PARAM) -> McclResult<()> {
    check(HOME_MODES_SET.contains(&h.wMode))?;
    check(h.wDirection <= 1)?;
    check(h.wSensorMode <= c::SL_NORMAL_CLOSE)?;
    check(h.nIndexCount >= 0)?;
    check(h.dfAccTime > 0.0 && h.dfDecTime > 0.0)?;
    range::time_ms(h.dfAccTime)?;
    range::time_ms(h.dfDecTime)?;
    range::speed(h.dfHighSpeed)?;
    range::speed(h.dfLowSpeed)?;
    range::position(h.dfOffset, conv_factor(mac))?;
    Ok(())
}

/// Pulses per user unit for a channel: dwPPR x dfGearRatio / dfPitch (examples manual §6:
/// motor coordinate = Cartesian coordinate x (dfGearRatio / dfPitch) x dwPPR).
pub fn conv_factor(p: &SYS_MAC_PARAM) -> f64 {
    f64::from(p.dwPPR) * p.dfGearRatio / p.dfPitch
}

/// One group: which channel of which card each of the 8 axes drives.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct GroupDef {
    /// The card the group's channels belong to.
    pub card: CardIx,
    /// Channel per axis X..B, `None` when the axis drives nothing.
    pub channels: [Option<ChannelIx>; AXES],
    /// Capacity of the group's motion command queue.
    pub queue_size: usize,
    /// The unit of the lengths the program gives and reads in this group: `UNIT_MM`
    /// (the mechanism parameters' own unit) or `UNIT_INCH` (`MCC_SetUnit`; see
    /// [`unit_scale`]).
    pub unit: i32,
}

/// Mechanism units (the unit of `dfPitch` and the work zone, taken to be mm) per unit of
/// a group in `unit`: 25.4 for `UNIT_INCH`, else 1.
pub fn unit_scale(unit: i32) -> f64 {
    if unit == c::UNIT_INCH {
        25.4
    } else {
        1.0
    }
}

impl GroupDef {
    /// Builds a group from `MCC_CreateGroupEx` arguments: each channel is -1 (unused) or
    /// 0..7, the card 0..11, no channel used twice, queue size 1..=10^6 (`PARAMETER_ERR`
    /// otherwise, as the vendor's library answers). A group of no axis is a group.
    pub fn new(map: [i32; AXES], card: i32, queue_size: i32) -> McclResult<GroupDef> {
        let card = CardIx::new(card)?;
        let mut channels = [None; AXES];
        for (slot, &ch) in channels.iter_mut().zip(map.iter()) {
            *slot = match ch {
                -1 => None,
                _ => Some(ChannelIx::new(ch)?),
            };
        }
        let queue_size = match usize::try_from(queue_size) {
            Ok(q) if (1..=MAX_QUEUE_SIZE).contains(&q) => q,
            _ => return Err(McclError::Parameter),
        };
        let used: Vec<usize> = channels.iter().flatten().map(|c| c.0).collect();
        for (i, a) in used.iter().enumerate() {
            if used[i + 1..].contains(a) {
                return Err(McclError::Parameter);
            }
        }
        Ok(GroupDef {
            card,
            channels,
            queue_size,
            unit: c::UNIT_MM,
        })
    }

    /// A group of no axis on `card` (what a group closed while the card runs leaves).
    pub fn none(card: CardIx) -> GroupDef {
        GroupDef {
            card,
            channels: [None; AXES],
            queue_size: 1,
            unit: c::UNIT_MM,
        }
    }

    /// The manual's default group: X..B on channels 0..7 of card 0 (§2.4.4).
    pub fn default_group() -> GroupDef {
        GroupDef {
            card: CardIx(0),
            channels: std::array::from_fn(|i| Some(ChannelIx(i))),
            queue_size: c::MOTION_QUEUE_SIZE as usize,
            unit: c::UNIT_MM,
        }
    }
}

/// Everything the program has configured.
#[derive(Debug, Clone)]
pub struct Config {
    /// Mechanism parameters per card and channel.
    pub mac: [[SYS_MAC_PARAM; AXES]; CARDS],
    /// Encoder configuration per card and channel.
    pub encoder: [[SYS_ENCODER_CONFIG; AXES]; CARDS],
    /// Go-home configuration per card and channel.
    pub home: [[SYS_HOME_CONFIG; AXES]; CARDS],
    /// Group slots; `None` is a free slot.
    pub groups: [Option<GroupDef>; GROUPS],
    /// Upper limit of the general-motion feed speed, UU/s (`MCC_SetSysMaxSpeed`).
    pub sys_max_speed: f64,
    /// Compensation tables set per card and channel (`MCC_SetCompParam`), applied by
    /// `MCC_UpdateCompParam`.
    pub comp: Vec<[Option<crate::vendor::SYS_COMP_PARAM>; AXES]>,
    /// The unit of each group slot (`MCC_SetUnit`); a group created or closed starts
    /// over in `UNIT_MM`.
    pub units: [i32; GROUPS],
    /// A group was created since the library loaded or `MCC_CloseAllGroups`: an init
    /// with an empty table then runs no group (the default group is for programs that
    /// never create one), as the vendor's library does.
    pub explicit_groups: bool,
}

/// The system maximum feed speed until `MCC_SetSysMaxSpeed` is called, UU/s: 100, as the
/// vendor's library reads right after init (the manuals give none).
pub const DEFAULT_SYS_MAX_SPEED: f64 = 100.0;

impl Default for Config {
    fn default() -> Self {
        Config {
            mac: [[default_mac_param(); AXES]; CARDS],
            encoder: [[default_encoder_config(); AXES]; CARDS],
            home: [[default_home_config(); AXES]; CARDS],
            groups: [None; GROUPS],
            sys_max_speed: DEFAULT_SYS_MAX_SPEED,
            comp: vec![[None; AXES]; CARDS],
            units: [c::UNIT_MM; GROUPS],
            explicit_groups: false,
        }
    }
}

impl Config {
    /// `MCC_SetMacParam`: validated mechanism parameters for one channel, refused
    /// (`PARAMETER_ERR`, nothing changed) when the channel's go-home offset would no
    /// longer be a position it can count.
    pub fn set_mac_param(&mut self, cd: CardIx, ch: ChannelIx, p: SYS_MAC_PARAM) -> McclResult<()> {
        validate_mac_param(&p)?;
        validate_home_config(&self.home[cd.0][ch.0], &p)?;
        self.mac[cd.0][ch.0] = p;
        Ok(())
    }

    /// `MCC_SetEncoderConfig`: a validated encoder configuration for one channel.
    pub fn set_encoder_config(
        &mut self,
        cd: CardIx,
        ch: ChannelIx,
        e: SYS_ENCODER_CONFIG,
    ) -> McclResult<()> {
        validate_encoder_config(&e)?;
        self.encoder[cd.0][ch.0] = e;
        Ok(())
    }

    /// `MCC_SetHomeConfig`: go-home parameters for one channel, validated against the
    /// channel's mechanism parameters as set.
    pub fn set_home_config(
        &mut self,
        cd: CardIx,
        ch: ChannelIx,
        h: SYS_HOME_CONFIG,
    ) -> McclResult<()> {
        validate_home_config(&h, &self.mac[cd.0][ch.0])?;
        self.home[cd.0][ch.0] = h;
        Ok(())
    }

    /// `MCC_SetCompParam`: the compensation tables of one channel, applied at
    /// `MCC_UpdateCompParam` (`wHome_No` above 255 is `PARAMETER_ERR`).
    pub fn set_comp_param(
        &mut self,
        cd: CardIx,
        ch: ChannelIx,
        p: crate::vendor::SYS_COMP_PARAM,
    ) -> McclResult<()> {
        if p.wHome_No > 255 {
            return Err(McclError::Parameter);
        }
        self.comp[cd.0][ch.0] = Some(p);
        Ok(())
    }

    /// A feed speed as general motion uses it: at most the system maximum
    /// (`MCC_SetSysMaxSpeed`).
    pub fn feed_speed(&self, v: f64) -> f64 {
        v.min(self.sys_max_speed)
    }

    /// Puts a group into the lowest free slot and returns its index
    /// (`GROUP_PARAMETER_ERR` when all 96 are used). A channel another group already
    /// drives is `PARAMETER_ERR`, as the vendor's library answers.
    pub fn create_group(&mut self, def: GroupDef) -> McclResult<usize> {
        let taken = self.groups.iter().flatten().any(|g| {
            g.card == def.card
                && g.channels
                    .iter()
                    .flatten()
                    .any(|c| def.channels.iter().flatten().any(|d| d == c))
        });
        if taken {
            return Err(McclError::Parameter);
        }
        let slot = self
            .groups
            .iter()
            .position(Option::is_none)
            .ok_or(McclError::Group)?;
        self.groups[slot] = Some(def);
        self.units[slot] = c::UNIT_MM;
        self.explicit_groups = true;
        Ok(slot)
    }

    /// The groups the card will run: those created, or the default group 0 when none
    /// were since the library loaded or `MCC_CloseAllGroups`.
    pub fn effective_groups(&self) -> Vec<(usize, GroupDef)> {
        let created: Vec<(usize, GroupDef)> = self
            .groups
            .iter()
            .enumerate()
            .filter_map(|(i, g)| g.map(|g| (i, g)))
            .collect();
        let mut groups = if created.is_empty() && !self.explicit_groups {
            vec![(0, GroupDef::default_group())]
        } else {
            created
        };
        for (i, d) in &mut groups {
            d.unit = self.units[*i];
        }
        groups
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn group_rules() {
        assert!(GroupDef::new([0, 1, 2, -1, -1, -1, -1, -1], 0, 10000).is_ok());
        // A group of no axis is a group: the vendor's library creates it (returns 0).
        assert!(GroupDef::new([-1; 8], 0, 10000).is_ok());
        assert_eq!(
            GroupDef::new([0, 0, -1, -1, -1, -1, -1, -1], 0, 10000),
            Err(McclError::Parameter),
            "two axes on one channel (as the vendor's library answers)"
        );
        assert_eq!(
            GroupDef::new([8, -1, -1, -1, -1, -1, -1, -1], 0, 10000),
            Err(McclError::Parameter)
        );
        assert_eq!(
            GroupDef::new([-2, 0, -1, -1, -1, -1, -1, -1], 0, 10000),
            Err(McclError::Parameter)
        );
        assert_eq!(GroupDef::new([0; 8], 12, 10000), Err(McclError::Parameter));
        assert_eq!(
            GroupDef::new([0, -1, -1, -1, -1, -1, -1, -1], 0, 0),
            Err(McclError::Parameter)
        );
    }

    #[test]
    fn default_group_when_none_created() {
        let cfg = Config::default();
        let g = cfg.effective_groups();
        assert_eq!(g.len(), 1);
        assert_eq!(g[0].0, 0);
        assert_eq!(g[0].1.channels[7], Some(ChannelIx(7)));
        assert_eq!(g[0].1.queue_size, 10000);
    }

    #[test]
    fn lowest_free_slot_and_full_table() {
        let mut cfg = Config::default();
        // One channel each: 12 cards x 8 channels are the 96 slots; a group of no axis
        // then finds none free. A channel another group has is refused first.
        let one = |i: usize| {
            let mut map = [-1; 8];
            map[0] = (i % AXES) as i32;
            GroupDef::new(map, (i / AXES) as i32, 10).unwrap()
        };
        for i in 0..GROUPS {
            assert_eq!(cfg.create_group(one(i)), Ok(i));
        }
        let none = GroupDef::new([-1; 8], 0, 10).unwrap();
        assert_eq!(cfg.create_group(none), Err(McclError::Group));
        assert_eq!(cfg.create_group(one(3)), Err(McclError::Parameter));
        cfg.groups[5] = None;
        assert_eq!(cfg.create_group(one(5)), Ok(5));
    }

    #[test]
    fn conv_factor_is_ppr_times_gear_over_pitch() {
        // examples manual §6: pulses = UU x (gear / pitch) x PPR; 1000 x 2 / 5 = 400
        let mut p = default_mac_param();
        p.dwPPR = 1000;
        p.dfGearRatio = 2.0;
        p.dfPitch = 5.0;
        assert_eq!(conv_factor(&p), 400.0);
    }

    #[test]
    fn validation_rejects_bad_values() {
        let good = default_mac_param();
        assert!(validate_mac_param(&good).is_ok());
        let bad = [
            SYS_MAC_PARAM {
                dfPitch: f64::NAN,
                ..good
            },
            SYS_MAC_PARAM {
                dfPitch: 0.0,
                ..good
            },
            SYS_MAC_PARAM {
                dfGearRatio: f64::INFINITY,
                ..good
            },
            SYS_MAC_PARAM { dwPPR: 0, ..good },
            SYS_MAC_PARAM {
                dfLowLimit: 1.0,
                dfHighLimit: 0.0,
                ..good
            },
            SYS_MAC_PARAM {
                wPulseMode: 4,
                ..good
            },
            SYS_MAC_PARAM {
                wCommandMode: 3,
                ..good
            },
            SYS_MAC_PARAM {
                wOverTravelUpSensorMode: 3,
                ..good
            },
            SYS_MAC_PARAM {
                dfHighLimit: -1.0,
                ..good
            },
            SYS_MAC_PARAM {
                dfLowLimit: 1.0,
                ..good
            },
        ];
        // Any direction is taken (nonzero reverses), as the vendor's library takes it.
        let dir2 = SYS_MAC_PARAM {
            wPosToEncoderDir: 2,
            ..good
        };
        assert_eq!(validate_mac_param(&dir2), Ok(()));
        for b in bad {
            assert_eq!(validate_mac_param(&b), Err(McclError::Parameter), "{b:?}");
        }
        let e = default_encoder_config();
        assert!(validate_encoder_config(&e).is_ok());
        for r in [0u16, 5, 8] {
            let b = SYS_ENCODER_CONFIG { wInputRate: r, ..e };
            assert_eq!(validate_encoder_config(&b), Err(McclError::Parameter));
        }
        assert_eq!(
            validate_encoder_config(&SYS_ENCODER_CONFIG { wType: 4, ..e }),
            Err(McclError::Parameter)
        );
        let h = default_home_config();
        let m = default_mac_param();
        assert!(validate_home_config(&h, &m).is_ok());
        // Modes 0..19 are kept, as the vendor's library keeps them (home_config_ranges);
        // 20 and above are refused.
        for mode in [0u16, 2, 17, 19] {
            let b = SYS_HOME_CONFIG { wMode: mode, ..h };
            assert_eq!(validate_home_config(&b, &m), Ok(()));
        }
        for mode in [20u16, 0xFFFF] {
            let b = SYS_HOME_CONFIG { wMode: mode, ..h };
            assert_eq!(validate_home_config(&b, &m), Err(McclError::Parameter));
        }
        let b = SYS_HOME_CONFIG {
            dfLowSpeed: f64::NAN,
            ..h
        };
        assert_eq!(validate_home_config(&b, &m), Err(McclError::Parameter));
    }
}
