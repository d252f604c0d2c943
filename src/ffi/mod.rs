//! The C entry points: argument checks, pointer checks, panic boundary, and Rust errors
//! to vendor return codes. One file per chapter of the manual; every entry point is
//! written out as a plain `#[no_mangle] pub extern "system" fn` (the vendor's `MCC_CALL`:
//! stdcall on 32-bit Windows, the C convention everywhere else; the `MCCL_Sim*` extension
//! and the MC3B library's `mcl_*` are `extern "C"`, as their headers declare no
//! convention) with its doc comment, so that searching for `fn MCC_Line` finds it. Its
//! body is one `ffi_boundary! { ... }` (see [`guard`]) that checks the arguments, calls
//! the core and maps the result; the `ffi_boundary` integration test rejects an exported
//! body that does not enter it, and the `exports_findable` test a function the headers
//! declare that is not written out exactly once.
//!
//! Entry points of one shape (one per axis, plane, channel kind, on/off pair, RIO and
//! ARIO, ...) share their logic through ordinary helper functions next to them, so each
//! body stays a line or a few: a call with the arguments C passed. The functions that take
//! one value or one pointer per axis name them `v0..v7` and `p0..p7` rather than by the
//! vendor's names (`wGain0`, `nPulse0`, ...): a Rust parameter name is not part of the C
//! interface, and the C header takes every prototype, names included, from the vendor
//! table; the generated test `tests/vendor_prototypes.rs` checks each Rust signature
//! against that table at compile time.
// The vendor's names live here and only here: the exports and their parameters carry
// the vendor's names (`MCC_Line`, `dfX`, `wCardType`).
#![allow(non_snake_case, non_camel_case_types, non_upper_case_globals)]

/// The panic boundary of an exported function: the block runs as a closure returning
/// `McclResult<R>` under [`guard`], which maps an error to the vendor code and a panic
/// to `RUN_TIME_ERR`. Every exported function's body in this module is exactly one of these.
macro_rules! ffi_boundary {
    (@mcl $($body:tt)*) => {
        $crate::ffi::guard_mcl(|| { $($body)* })
    };
    ($($body:tt)*) => {
        $crate::ffi::guard(|| { $($body)* })
    };
}

pub mod adc;
pub mod cone;
pub mod converter_timing;
pub mod coordinate;
pub mod custom;
pub mod dac;
pub mod encoder;
pub mod filters;
pub mod handshake;
pub mod home;
pub mod isr;
pub mod jog;
pub mod kinematics;
pub mod legacy_params;
pub mod limits;
pub mod local_io;
pub mod mcl;
pub mod motion;
pub mod position;
pub mod ptp;
pub mod rio;
pub mod sim;
pub mod status;
pub mod system;
pub mod timer;
pub mod trajectory;
pub mod units;

use crate::config::{CardIx, ChannelIx};
use crate::engine::command::{Command, Ctx};
use crate::error::{McclError, McclResult};
use crate::vendor::WORD;
use std::os::raw::c_int;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// How an entry point's return type reports a failure.
pub trait FfiReturn {
    /// The value returned for `e`.
    fn from_error(e: McclError) -> Self;
}

impl FfiReturn for c_int {
    fn from_error(e: McclError) -> Self {
        e.code()
    }
}

/// Functions returning `double` report errors as the (negative) vendor code converted to
/// double; none of their valid results is negative.
impl FfiReturn for f64 {
    fn from_error(e: McclError) -> Self {
        f64::from(e.code())
    }
}

impl FfiReturn for () {
    fn from_error(_: McclError) -> Self {}
}

/// Runs `f`, turning an error into the vendor code and a panic into `RUN_TIME_ERR`
/// (no panic ever crosses the C boundary).
///
/// A panic is a defect of the library, and the state it interrupted may be half
/// updated, so it leaves a defined state behind: a panic inside a call on one group
/// ([`with_group`]) stops that group; any other stops every group of the running system.
/// A stopped group stands where it is, its queue is dropped and it records
/// [`ERR_INTERNAL`](crate::engine::safety::ERR_INTERNAL) (0xF1FF), so it runs nothing
/// until the program calls `MCC_ClearError`.
pub fn guard<R: FfiReturn>(f: impl FnOnce() -> McclResult<R>) -> R {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(Ok(v)) => v,
        Ok(Err(e)) => R::from_error(e),
        Err(_) => {
            if !GROUP_STOPPED_AFTER_PANIC.with(|s| s.replace(false)) {
                // Best effort: a second panic here must not cross the boundary either.
                let _ = catch_unwind(|| {
                    if let Ok(shared) = crate::system::active() {
                        shared.stop_all_for_internal_error();
                    }
                });
            }
            R::from_error(McclError::RunTime)
        }
    }
}

/// [`guard`] for the MC3B library's entry points (`ffi_boundary! { @mcl ... }`), whose
/// bodies return their §4 status: a panic is `MCL_SERIAL_PORT_ERROR`, the guide's
/// low-level error, after [`crate::mc3b::mcl::after_panic`] has stopped the board's motors
/// and released the port (what the interrupted call left half done is not trusted).
pub fn guard_mcl(f: impl FnOnce() -> c_int) -> c_int {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(status) => status,
        Err(_) => {
            crate::mc3b::mcl::after_panic();
            crate::mc3b::mcl::MCL_SERIAL_PORT_ERROR
        }
    }
}

thread_local! {
    /// Set by [`with_group`] when it already stopped the group a panic interrupted.
    static GROUP_STOPPED_AFTER_PANIC: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Runs `f` on the peripherals of card `wCardIndex` of the running system:
/// `INITIAL_MOTION_ERR` before init, `PARAMETER_ERR` for a card not passed to
/// `MCC_InitSystem`. Takes no other lock.
pub fn with_card<R>(
    wCardIndex: u16,
    f: impl FnOnce(&mut crate::card::Peripherals) -> crate::error::McclResult<R>,
) -> crate::error::McclResult<R> {
    let shared = crate::system::active()?;
    let cd = shared.card(crate::config::CardIx::new(wCardIndex)?)?;
    let mut p = shared.periph(cd).ok_or(McclError::Parameter)?.lock();
    f(&mut p)
}

/// A card index as C passed it (`wCardIndex`), not yet checked. The accessors below
/// take `Channel` and `Card` in the vendor's order (channel first), typed so that a
/// swapped pair does not compile.
#[derive(Debug, Clone, Copy)]
pub struct Card(pub u16);

/// A channel index as C passed it (`wChannel`), not yet checked.
#[derive(Debug, Clone, Copy)]
pub struct Channel(pub u16);

/// Runs setter `f` on the peripherals of card `wCardIndex` (see [`with_card`]); `NO_ERR`.
pub fn card_do<D: Done>(
    wCardIndex: u16,
    f: impl FnOnce(&mut crate::card::Peripherals) -> D,
) -> McclResult<c_int> {
    with_card(wCardIndex, |p| f(p).done())?;
    Ok(crate::vendor::consts::NO_ERR)
}

/// After init (`INITIAL_MOTION_ERR` whatever the arguments), checks the index `check`
/// returns, then runs setter `f` with it on the peripherals of card `wCardIndex`; `NO_ERR`.
pub fn card_do_at<I, D: Done>(
    wCardIndex: u16,
    check: impl FnOnce() -> McclResult<I>,
    f: impl FnOnce(&mut crate::card::Peripherals, I) -> D,
) -> McclResult<c_int> {
    initialised()?;
    let i = check()?;
    card_do(wCardIndex, |p| f(p, i))
}

/// Runs `f` on the simulated machine with its lock held and the index of card `cd`.
/// `INITIAL_MOTION_ERR` before init, then `PARAMETER_ERR` for a bad card.
pub fn with_machine<R>(
    cd: Card,
    f: impl FnOnce(&mut crate::machine::Machine, usize) -> McclResult<R>,
) -> McclResult<R> {
    let shared = crate::system::active()?;
    let cd = shared.card(card(cd.0)?)?;
    let mut m = shared.lock_machine();
    f(&mut m, cd)
}

/// Runs `f` on the trigger state of card `cd` (see [`with_machine`]).
pub fn with_card_triggers<R>(
    cd: Card,
    f: impl FnOnce(&mut crate::machine::triggers::CardTriggers) -> McclResult<R>,
) -> McclResult<R> {
    with_machine(cd, |m, cd| f(m.triggers_mut(cd)))
}

/// Runs `f` on channel `ch` of card `cd` of the simulated machine with its lock held.
/// `PARAMETER_ERR` for a bad card or channel (checked first, in that order), then
/// `INITIAL_MOTION_ERR` before init.
pub fn with_machine_channel<R>(
    ch: Channel,
    cd: Card,
    f: impl FnOnce(&mut crate::machine::Channel) -> McclResult<R>,
) -> McclResult<R> {
    let (cd, ch) = (card(cd.0)?, channel(ch.0)?);
    let shared = crate::system::active()?;
    let cd = shared.card(cd)?;
    let mut m = shared.lock_machine();
    f(m.channel_mut(cd, ch.0).ok_or(McclError::Parameter)?)
}

/// `INITIAL_MOTION_ERR` until `MCC_InitSystem` has run: checked first by the calls that
/// answer so whatever their other arguments are.
pub fn initialised() -> McclResult<()> {
    crate::system::active().map(|_| ())
}

/// A card index from C.
pub fn card(w: u16) -> McclResult<CardIx> {
    CardIx::new(w)
}

/// A channel index from C.
pub fn channel(w: u16) -> McclResult<ChannelIx> {
    ChannelIx::new(w)
}

/// A finite number from C (`PARAMETER_ERR` for NaN and infinities).
pub fn finite(x: f64) -> McclResult<f64> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(McclError::Parameter)
    }
}

/// Reads a struct the caller passed by pointer (`PARAMETER_ERR` for NULL).
///
/// # Safety
/// `p` must be NULL or point to a readable, initialised `T`.
pub unsafe fn read_in<T: Copy>(p: *const T) -> McclResult<T> {
    if p.is_null() {
        return Err(McclError::Parameter);
    }
    // SAFETY: non-null, and the caller guarantees it points to a readable T; unaligned
    // reads are tolerated because C callers may pass packed buffers.
    Ok(unsafe { p.read_unaligned() })
}

/// An output pointer from C, checked when it is made: NULL is refused with
/// `PARAMETER_ERR`. A call makes all its outputs first (so a NULL among them fails
/// before anything changes), then writes them.
pub struct Out<T>(std::ptr::NonNull<T>);

impl<T> Out<T> {
    /// Checks `p` (`PARAMETER_ERR` for NULL).
    ///
    /// # Safety
    /// `p` must be NULL or point to memory writable as a `T` (alignment not needed) for
    /// as long as the `Out` lives.
    pub unsafe fn new(p: *mut T) -> McclResult<Self> {
        std::ptr::NonNull::new(p)
            .map(Out)
            .ok_or(McclError::Parameter)
    }

    /// Checks every pointer of `p` (`PARAMETER_ERR` if one is NULL).
    ///
    /// # Safety
    /// As [`Out::new`], for each pointer.
    pub unsafe fn each<const N: usize>(p: [*mut T; N]) -> McclResult<[Self; N]> {
        p.iter().try_for_each(|q| {
            if q.is_null() {
                Err(McclError::Parameter)
            } else {
                Ok(())
            }
        })?;
        // SAFETY: every pointer was found non-null just above.
        Ok(p.map(|q| Out(unsafe { std::ptr::NonNull::new_unchecked(q) })))
    }

    /// Writes the result.
    pub fn write(self, v: T) {
        // SAFETY: non-null (checked by `new`) and writable (`new`'s contract); C callers
        // may pass packed buffers, so the write is unaligned.
        unsafe { self.0.as_ptr().write_unaligned(v) }
    }
}

/// Reads a channel's configuration struct from C (card, then channel, then NULL checked)
/// and hands it to the core's setter, which validates it.
///
/// # Safety
/// `p` must be NULL or point to a readable `T`.
pub unsafe fn set_channel_config<T: Copy>(
    p: *const T,
    wChannel: WORD,
    wCardIndex: WORD,
    set: impl FnOnce(&mut crate::config::Config, CardIx, ChannelIx, T) -> McclResult<()>,
) -> McclResult<c_int> {
    let (cd, ch) = (card(wCardIndex)?, channel(wChannel)?);
    // Once the system runs, only its cards (as the vendor's library answers).
    if let Ok(shared) = crate::system::active() {
        shared.card(cd)?;
    }
    // SAFETY: NULL is rejected; otherwise the caller passes a readable T.
    let v = unsafe { read_in(p) }?;
    crate::system::config(|c| set(c, cd, ch, v))?;
    Ok(crate::vendor::consts::NO_ERR)
}

/// Writes a channel's configuration struct, as last set, to C (card, then channel, then
/// NULL checked).
///
/// # Safety
/// `p` must be NULL or point to memory writable as a `T`.
pub unsafe fn get_channel_config<T: Copy>(
    p: *mut T,
    wChannel: WORD,
    wCardIndex: WORD,
    table: impl FnOnce(&crate::config::Config) -> &[[T; crate::config::AXES]; crate::config::CARDS],
) -> McclResult<c_int> {
    // SAFETY: forwarded under this function's contract.
    unsafe { read_channel_config(p, wChannel, wCardIndex, |c, cd, ch| table(c)[cd.0][ch.0]) }
}

/// Writes what `get` makes of a channel's configuration to C (card, then channel, then
/// NULL checked).
///
/// # Safety
/// `p` must be NULL or point to memory writable as a `T`.
pub unsafe fn read_channel_config<T>(
    p: *mut T,
    wChannel: WORD,
    wCardIndex: WORD,
    get: impl FnOnce(&crate::config::Config, CardIx, ChannelIx) -> T,
) -> McclResult<c_int> {
    let (cd, ch) = (card(wCardIndex)?, channel(wChannel)?);
    // SAFETY: NULL or writable, as this function's contract requires.
    let out = unsafe { Out::new(p) }?;
    out.write(crate::system::config(|c| get(c, cd, ch)));
    Ok(crate::vendor::consts::NO_ERR)
}

/// What a core setter returns: nothing (it cannot fail) or `McclResult<()>`; the
/// accessors below take either.
pub trait Done {
    /// The setter's result.
    fn done(self) -> McclResult<()>;
}

impl Done for () {
    fn done(self) -> McclResult<()> {
        Ok(())
    }
}

impl Done for McclResult<()> {
    fn done(self) -> McclResult<()> {
        self
    }
}

/// A getter with one output: `p` is checked (NULL refused with `PARAMETER_ERR`) before
/// `get` runs, then what `get` returns is written; `NO_ERR`.
///
/// # Safety
/// `p` must be NULL or point to memory writable as a `T` (alignment not needed).
pub unsafe fn write_out<T>(p: *mut T, get: impl FnOnce() -> McclResult<T>) -> McclResult<c_int> {
    // SAFETY: NULL or writable, as this function's contract requires.
    let out = unsafe { Out::new(p) }?;
    out.write(get()?);
    Ok(crate::vendor::consts::NO_ERR)
}

/// A getter with `N` outputs (one per axis or channel): every pointer is checked (one
/// NULL is refused with `PARAMETER_ERR`) before `get` runs, then what `get` returns is
/// written; `NO_ERR`.
///
/// # Safety
/// Every pointer of `p` must be NULL or point to memory writable as a `T`.
pub unsafe fn write_outs<T, const N: usize>(
    p: [*mut T; N],
    get: impl FnOnce() -> McclResult<[T; N]>,
) -> McclResult<c_int> {
    // SAFETY: NULL or writable, as this function's contract requires.
    let outs = unsafe { Out::each(p) }?;
    write_each(outs, get()?);
    Ok(crate::vendor::consts::NO_ERR)
}

/// What `read` takes from the published snapshot of running group `g` (no engine lock;
/// see `Shared::published`): each status getter reads only the words it returns.
pub fn read_published<R>(
    g: u16,
    read: impl FnOnce(&crate::engine::snapshot::SnapshotCell) -> R,
) -> McclResult<R> {
    Ok(read(crate::system::active()?.published(g)?))
}

/// Writes `N` results through outputs made by [`Out::each`].
pub fn write_each<T, const N: usize>(outs: [Out<T>; N], v: [T; N]) {
    for (o, x) in outs.into_iter().zip(v) {
        o.write(x);
    }
}

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_panic;

/// Runs `f` on running group `g` with its lock held, then publishes the group's state.
/// `INITIAL_MOTION_ERR` before init, `GROUP_PARAMETER_ERR` for a group that does not run.
pub fn with_group<R>(
    g: u16,
    f: impl FnOnce(&mut crate::engine::group::GroupState) -> McclResult<R>,
) -> McclResult<R> {
    let shared = crate::system::active()?;
    let mut grp = shared.group(g)?;
    let r = match catch_unwind(AssertUnwindSafe(|| f(&mut grp))) {
        Ok(r) => r,
        Err(panic) => {
            // The group may be half updated: stop it where it stands (see `guard`).
            grp.stop_for(Some(crate::engine::safety::ERR_INTERNAL));
            shared.publish(&mut grp);
            GROUP_STOPPED_AFTER_PANIC.with(|s| s.set(true));
            drop(grp);
            std::panic::resume_unwind(panic);
        }
    };
    // Published on failure too: a refused arc still records its error (0xF104).
    shared.publish(&mut grp);
    r
}

/// Changes running group `g` with `f` (see [`with_group`]); returns `NO_ERR`.
pub fn update_group(
    g: u16,
    f: impl FnOnce(&mut crate::engine::group::GroupState),
) -> McclResult<c_int> {
    with_group(g, |grp| {
        f(grp);
        Ok(crate::vendor::consts::NO_ERR)
    })
}

/// Queues `cmd` into `grp` for the program; returns its index. Refused
/// (`COMMAND_NOTACCEPTED_ERR`) from inside a callback of the group itself, which the
/// engine thread runs for it and which would wait for itself; the library's fault point
/// "enqueue" sits half-way through changing the queue.
pub(crate) fn enqueue(
    grp: &mut crate::engine::group::GroupState,
    cmd: Command,
) -> McclResult<c_int> {
    if crate::engine::custom::in_callback() == Some(grp.index()) {
        return Err(McclError::NotAccepted);
    }
    grp.enqueue_probed(cmd, crate::fault::point)
}

/// Plans a command with the group's context at call time and queues it; returns the
/// command index. A degenerate arc also records error 0xF104 (user manual §2.6.3 VI).
pub fn queue(g: u16, plan: impl FnOnce(&Ctx<'_>) -> McclResult<Command>) -> McclResult<c_int> {
    with_group(g, |grp| {
        let cmd = plan(&grp.ctx())?;
        enqueue(grp, cmd)
    })
}

/// Like [`queue`] for arcs, circles and helices. A curve with no geometry (coincident or
/// collinear points, a zero radius) is queued all the same and records 0xF104 when it
/// starts, as the vendor's library does.
pub fn queue_curve(
    g: u16,
    plan: impl FnOnce(&Ctx<'_>) -> Result<crate::planner::Path, crate::planner::PlanError>,
    kind: crate::engine::command::Curve,
) -> McclResult<c_int> {
    with_group(g, |grp| {
        let cmd = match plan(&grp.ctx()) {
            Ok(path) => grp.ctx().curve(path, kind)?,
            Err(crate::planner::PlanError::BadArc) => grp.ctx().fault(kind, ERR_BAD_ARC),
            Err(_) => return Err(McclError::Parameter),
        };
        enqueue(grp, cmd)
    })
}

/// Error record of a bad arc or circle command (docs/vendor-interface.md).
pub const ERR_BAD_ARC: i32 = crate::error_record::ErrorRecord::BadArc.code();

/// An axis named by the vendor's `char cAxis`: its number 0..7 (X..B). Anything else,
/// the letters too, is `GROUP_PARAMETER_ERR`, as the vendor's library answers.
pub fn axis(c: std::os::raw::c_char) -> McclResult<usize> {
    let b = c as u8;
    match b {
        0..=7 => Ok(usize::from(b)),
        _ => Err(McclError::Group),
    }
}

/// An acc/dec shape from the vendor's `char`: 'T' or 'S' (either case).
pub fn shape(c: std::os::raw::c_char) -> McclResult<crate::planner::Shape> {
    crate::planner::Shape::from_char((c as u8).to_ascii_uppercase()).ok_or(McclError::Parameter)
}

/// The vendor's `char` for a shape.
pub fn shape_char(s: crate::planner::Shape) -> std::os::raw::c_char {
    (match s {
        crate::planner::Shape::T => b'T',
        crate::planner::Shape::S => b'S',
    }) as std::os::raw::c_char
}

/// A shape as the vendor's getters answer it: 0 'T', 1 'S'.
pub fn shape_code(s: crate::planner::Shape) -> c_int {
    match s {
        crate::planner::Shape::T => 0,
        crate::planner::Shape::S => 1,
    }
}

/// A count as the vendor's `WORD` outputs report it: at most 65535.
pub fn word_count(n: usize) -> crate::vendor::WORD {
    n.min(usize::from(crate::vendor::WORD::MAX)) as crate::vendor::WORD
}

/// An axis mask from C: bits 0..7 (X..B); a higher bit is `PARAMETER_ERR`.
pub fn axis_mask(dwAxisMask: crate::vendor::DWORD) -> McclResult<u32> {
    bits(dwAxisMask, 0xFF)
}

/// A bit mask from C with no bit outside `allowed` (`PARAMETER_ERR` otherwise).
pub fn bits<T: Into<u32> + Copy>(w: T, allowed: u32) -> McclResult<T> {
    if w.into() & !allowed != 0 {
        Err(McclError::Parameter)
    } else {
        Ok(w)
    }
}

/// An index from C below `n`: a point, an axis, a side (`PARAMETER_ERR` otherwise).
pub fn index(w: WORD, n: usize) -> McclResult<usize> {
    let i = usize::from(w);
    if i < n {
        Ok(i)
    } else {
        Err(McclError::Parameter)
    }
}

/// A switch from C: 1 on, 0 off (`PARAMETER_ERR` otherwise).
pub fn flag(v: impl Into<i64>) -> McclResult<bool> {
    match v.into() {
        0 => Ok(false),
        1 => Ok(true),
        _ => Err(McclError::Parameter),
    }
}

/// `byCirDir`: counter-clockwise (true) or clockwise.
fn direction(byCirDir: crate::vendor::BYTE) -> McclResult<bool> {
    // `CIR_CW` (0) or anything else: counter-clockwise, as the vendor's library takes it.
    Ok(i32::from(byCirDir) != crate::vendor::consts::CIR_CW)
}

/// A point of a plane from C: both coordinates finite.
fn finite2(v: [f64; 2]) -> McclResult<[f64; 2]> {
    Ok([finite(v[0])?, finite(v[1])?])
}

/// Checks that 8 numbers from C are finite.
pub fn finite8(v: [f64; 8]) -> McclResult<[f64; 8]> {
    v.iter().try_for_each(|&x| finite(x).map(|_| ()))?;
    Ok(v)
}
