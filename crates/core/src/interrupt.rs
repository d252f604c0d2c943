//! The interrupt causes of the virtual card, as data: the callback kinds, one cause
//! ([`Interrupt`]) and the causes raised on a card since the last delivery ([`Pending`]),
//! laid out as the bytes of the vendor's ISR structs. A leaf module: the card's
//! peripherals and the simulated machine raise causes, the engine delivers them
//! (`engine::isr`).

use crate::vendor::{ADCINT, ENCINT, HSKINT, LIOINT, PCLINT, RIOINT, TMRINT};

/// The callback kinds, in delivery order.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// Local I/O (`LIOISR`, `LIOINT`).
    Lio = 0,
    /// Encoder index and compare (`ENCISR`, `ENCINT`).
    Enc = 1,
    /// Position control loop (`PCLISR`, `PCLINT`).
    Pcl = 2,
    /// A/D converter (`ADCISR`, `ADCINT`).
    Adc = 3,
    /// Timer (`TMRISR`, `TMRINT`).
    Tmr = 4,
    /// Remote I/O (`RIOISR`, `RIOINT`).
    Rio = 5,
    /// Handshake (`HSKISR`, `HSKINT`).
    Hsk = 6,
}

/// Number of callback kinds.
pub const KINDS: usize = 7;

/// One interrupt cause. Channel/input numbers are 0..=7.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Interrupt {
    /// Limit switch + of a channel (`LIOINT.OTPn`).
    LioOtp(u8),
    /// Limit switch − of a channel (`LIOINT.OTNn`).
    LioOtn(u8),
    /// Home sensor of a channel (`LIOINT.HOMEn`).
    LioHome(u8),
    /// Encoder index of a channel (`ENCINT.INDEXn`).
    EncIndex(u8),
    /// Encoder compare of a channel (`ENCINT.COMPn`).
    EncComp(u8),
    /// Closed-loop error over the positive bound (`PCLINT.OVPn`).
    PclOvp(u8),
    /// Closed-loop error over the negative bound (`PCLINT.OVNn`).
    PclOvn(u8),
    /// ADC comparator of a channel (`ADCINT.COMPn`).
    AdcComp(u8),
    /// An ADC conversion completed (`ADCINT.CONV`).
    AdcConv,
    /// The tagged ADC channel completed a conversion (`ADCINT.TAG`).
    AdcTag,
    /// The timer expired this many times (`TMRINT.TIMER`).
    Timer(u64),
    /// Remote digital input n (`RIOINT.RDIn`).
    RioInput(u8),
    /// A remote I/O transmission failed (byte 8 after `RIOINT`: the `FAIL` field of the
    /// driver's longer RIOINT; programs using MCCL.h's 8-byte RIOINT see all RDI at 0).
    RioFail,
    /// Handshake (`HSKINT.HANDSHAKE`).
    Handshake,
}

/// The causes raised on one card since the last delivery, as the bytes of the ISR
/// structs (every field of those structs is a BYTE).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Pending {
    /// `LIOINT`: OTP0..7, OTN0..7, HOME0..7.
    pub lio: [u8; 24],
    /// `ENCINT`: INDEX0..7, COMP0..7.
    pub enc: [u8; 16],
    /// `PCLINT`: OVP0..7, OVN0..7.
    pub pcl: [u8; 16],
    /// `ADCINT`: COMP0..7, CONV, TAG.
    pub adc: [u8; 10],
    /// `TMRINT`: TIMER.
    pub tmr: [u8; 1],
    /// `RIOINT`: RDI0..7, then FAIL.
    pub rio: [u8; 9],
    /// `HSKINT`: HANDSHAKE.
    pub hsk: [u8; 1],
}

const _: () = {
    assert!(std::mem::size_of::<LIOINT>() == 24);
    assert!(std::mem::size_of::<ENCINT>() == 16);
    assert!(std::mem::size_of::<PCLINT>() == 16);
    assert!(std::mem::size_of::<ADCINT>() == 10);
    assert!(std::mem::size_of::<RIOINT>() == 8);
    assert!(std::mem::size_of::<TMRINT>() == 1);
    assert!(std::mem::size_of::<HSKINT>() == 1);
};

fn bump(b: &mut u8, n: u64) {
    *b = u8::try_from(u64::from(*b).saturating_add(n)).unwrap_or(u8::MAX);
}

impl Pending {
    /// Records one cause (a channel or input number above 7 is ignored).
    pub fn raise(&mut self, i: Interrupt) {
        let ix = |n: u8| usize::from(n);
        if let Interrupt::LioOtp(n)
        | Interrupt::LioOtn(n)
        | Interrupt::LioHome(n)
        | Interrupt::EncIndex(n)
        | Interrupt::EncComp(n)
        | Interrupt::PclOvp(n)
        | Interrupt::PclOvn(n)
        | Interrupt::AdcComp(n)
        | Interrupt::RioInput(n) = i
        {
            if n > 7 {
                return;
            }
        }
        match i {
            Interrupt::LioOtp(n) => bump(&mut self.lio[ix(n)], 1),
            Interrupt::LioOtn(n) => bump(&mut self.lio[8 + ix(n)], 1),
            Interrupt::LioHome(n) => bump(&mut self.lio[16 + ix(n)], 1),
            Interrupt::EncIndex(n) => bump(&mut self.enc[ix(n)], 1),
            Interrupt::EncComp(n) => bump(&mut self.enc[8 + ix(n)], 1),
            Interrupt::PclOvp(n) => bump(&mut self.pcl[ix(n)], 1),
            Interrupt::PclOvn(n) => bump(&mut self.pcl[8 + ix(n)], 1),
            Interrupt::AdcComp(n) => bump(&mut self.adc[ix(n)], 1),
            Interrupt::AdcConv => bump(&mut self.adc[8], 1),
            Interrupt::AdcTag => bump(&mut self.adc[9], 1),
            Interrupt::Timer(k) => bump(&mut self.tmr[0], k),
            Interrupt::RioInput(n) => bump(&mut self.rio[ix(n)], 1),
            Interrupt::RioFail => bump(&mut self.rio[8], 1),
            Interrupt::Handshake => bump(&mut self.hsk[0], 1),
        }
    }

    /// Whether nothing was raised.
    pub fn is_empty(&self) -> bool {
        *self == Pending::default()
    }

    /// The bytes of one kind's struct.
    pub fn bytes(&self, k: Kind) -> &[u8] {
        match k {
            Kind::Lio => &self.lio,
            Kind::Enc => &self.enc,
            Kind::Pcl => &self.pcl,
            Kind::Adc => &self.adc,
            Kind::Tmr => &self.tmr,
            Kind::Rio => &self.rio,
            Kind::Hsk => &self.hsk,
        }
    }
}

/// The delivery order of the kinds.
pub const ORDER: [Kind; KINDS] = [
    Kind::Lio,
    Kind::Enc,
    Kind::Pcl,
    Kind::Adc,
    Kind::Tmr,
    Kind::Rio,
    Kind::Hsk,
];
