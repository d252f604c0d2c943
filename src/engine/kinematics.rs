//! Robot kinematics of the virtual card (`MCC_SetKinematicTrans`): the program's forward
//! and inverse kinematics, its extension buffer, the joint point-to-point move
//! (`MCC_PtP_V6`), and the stage that runs the kinematics after every tick.
//!
//! # How a kinematic group runs
//!
//! The group's commands, its planner and its command position are Cartesian (X, Y, Z,
//! RX, RY, RZ and two aux axes in the axes X..B); its channels carry joints
//! ([`crate::engine::group::kinematics`] keeps them). The user's callbacks never run
//! with a library lock held, so they may call any `MCC_*` function:
//!
//! 1. Tick k (`super::tick`): the group samples its Cartesian path as any group does,
//!    then applies the joints the stage computed after tick k−1; the channels get those
//!    joints' pulses.
//! 2. After tick k, with every lock released (`Shared::kinematics_stage`, called by
//!    the engine thread's loop): for each kinematic group, read under its lock the
//!    Cartesian sample of tick k (the point the joints of tick k+1 go to), release the
//!    lock, call the inverse kinematics with it and the previous joints, take the lock
//!    again and store the joints for tick k+1 to apply.
//!
//! So the joints follow the Cartesian planner one interpolation period later, and the
//! group reports `GMS_STOP` only once the joints of the planner's last point are out.
//! Everything happens on the engine thread in tick order: the same under the fast,
//! stepped and realtime clocks. A `FALSE` (or a non-finite joint) from the inverse
//! kinematics stops the group with error record 0xF106: the joints stay where they were
//! (no jump) and the Cartesian position goes back to the last point they reached.

use super::shared::Shared;
use crate::config::AXES;
use crate::planner::{Axes, PlanError, PtpMove, Shape};
use crate::vendor::{BOOL, DWORD, FWDKINEFUN, INIT_EXTENSION, INVKINEFUN};
use std::ffi::c_void;
use std::os::raw::c_int;
use std::sync::atomic::Ordering;
use std::sync::Arc;

/// The largest extension buffer `MCC_SetKinematicTrans` allocates (bytes): 16 MiB, far
/// more than a robot's parameters (a few hundred doubles) need; a larger size is taken
/// for a mistake (an uninitialised or negative number) and refused.
pub const MAX_EXTENSION_BYTES: u64 = 16 << 20;

/// The number of axes the kinematics callbacks get (`nSynAxisNum`): the arrays they
/// receive always hold the group's eight axes.
pub const KIN_AXES: c_int = AXES as c_int;

/// A kinematic group's extension buffer: zeroed, 16-byte aligned, owned by the library
/// and handed to every kinematics call as `pvExtension`. Only the program's callbacks
/// read or write it; the library never looks inside.
#[derive(Debug)]
pub struct Extension {
    /// The memory (`u128` words for the alignment); `None` for size 0.
    buf: Option<std::ptr::NonNull<u128>>,
    words: usize,
}

// SAFETY: the library never reads or writes the buffer; it only hands its address to the
// program's callbacks, which own its contents and their synchronisation (the vendor's
// contract: the program's kinematics run on the library's thread and the program's).
unsafe impl Send for Extension {}
// SAFETY: as for Send: shared references only give out the address.
unsafe impl Sync for Extension {}

impl Extension {
    /// A zeroed buffer of `bytes` bytes (`PARAMETER_ERR` beyond
    /// [`MAX_EXTENSION_BYTES`] or when the memory cannot be had).
    pub fn new(bytes: u64) -> crate::error::McclResult<Extension> {
        if bytes > MAX_EXTENSION_BYTES {
            return Err(crate::error::McclError::Parameter);
        }
        let words =
            usize::try_from(bytes.div_ceil(16)).map_err(|_| crate::error::McclError::Parameter)?;
        if words == 0 {
            return Ok(Extension {
                buf: None,
                words: 0,
            });
        }
        let mut v: Vec<u128> = Vec::new();
        v.try_reserve_exact(words)
            .map_err(|_| crate::error::McclError::Parameter)?;
        v.resize(words, 0);
        let b = Box::into_raw(v.into_boxed_slice());
        Ok(Extension {
            buf: std::ptr::NonNull::new(b.cast::<u128>()),
            words,
        })
    }

    /// The address the callbacks get (NULL for size 0).
    pub fn ptr(&self) -> *mut c_void {
        self.buf
            .map_or(std::ptr::null_mut(), |p| p.as_ptr().cast::<c_void>())
    }
}

impl Drop for Extension {
    fn drop(&mut self) {
        if let Some(p) = self.buf.take() {
            let slice = std::ptr::slice_from_raw_parts_mut(p.as_ptr(), self.words);
            // SAFETY: made by `Box::into_raw` of a boxed slice of `words` u128 in `new`,
            // dropped once (`take`).
            drop(unsafe { Box::from_raw(slice) });
        }
    }
}

/// The program's kinematics of one group: its callbacks (checked non-NULL) and the
/// extension they share.
#[derive(Debug, Clone)]
pub struct KinFns {
    /// Forward kinematics (joints → Cartesian).
    pub fwd: FWDKINEFUN,
    /// Inverse kinematics (Cartesian → joints).
    pub inv: INVKINEFUN,
    /// The extension buffer.
    pub ext: Arc<Extension>,
}

impl KinFns {
    /// Calls the forward kinematics of group `g` (no lock may be held): the Cartesian
    /// position of `joints`, or `None` when it returns `FALSE` or a non-finite number.
    pub fn forward(&self, g: usize, joints: &Axes, posture: &mut DWORD) -> Option<Axes> {
        let f = self.fwd?;
        let mut out = *joints;
        // SAFETY: a C function pointer the program registered with this signature; the
        // arrays hold AXES doubles each, the posture and extension pointers are valid
        // for the call.
        let ok: BOOL = unsafe {
            f(
                c_int::try_from(g).unwrap_or(0),
                KIN_AXES,
                joints.as_ptr(),
                out.as_mut_ptr(),
                posture,
                self.ext.ptr(),
            )
        };
        (ok != 0 && out.iter().all(|x| x.is_finite())).then_some(out)
    }

    /// Calls the inverse kinematics of group `g` (no lock may be held): the joints of
    /// `cart` given the previous joints `prev`, or `None` when it returns `FALSE` or a
    /// non-finite joint.
    pub fn inverse(&self, g: usize, cart: &Axes, prev: &Axes, posture: &mut DWORD) -> Option<Axes> {
        let f = self.inv?;
        let mut out = *prev;
        // SAFETY: as in `forward`; `prev` and `out` are distinct arrays of AXES doubles.
        let ok: BOOL = unsafe {
            f(
                c_int::try_from(g).unwrap_or(0),
                KIN_AXES,
                cart.as_ptr(),
                prev.as_ptr(),
                out.as_mut_ptr(),
                posture,
                self.ext.ptr(),
            )
        };
        (ok != 0 && out.iter().all(|x| x.is_finite())).then_some(out)
    }
}

/// Calls the program's extension initialiser once on `ext` (no lock may be held).
pub fn init_extension(f: INIT_EXTENSION, ext: &Extension) {
    if let Some(f) = f {
        // SAFETY: a C function pointer the program registered; the buffer lives as long
        // as `ext`.
        unsafe { f(ext.ptr()) }
    }
}

/// `MCC_PtP_V6`: a point-to-point move of the joints. It is planned when it starts, from
/// the joints then (which the Cartesian moves before it leave only at run time), with
/// the group's ramps and speeds captured when it was queued; all joints start and end
/// together. Its Cartesian end is the forward kinematics of its target, computed when it
/// was queued.
#[derive(Debug, Clone)]
pub struct JointMove {
    /// Joint targets.
    pub target: Axes,
    /// Cartesian position where it starts (the end of the queue before it).
    pub cart_start: Axes,
    /// Cartesian position of `target`.
    pub cart_end: Axes,
    /// Per-joint speed, UU/s.
    pub speed: Axes,
    /// Acceleration and deceleration periods.
    pub ramps: (u32, u32),
    /// Acceleration and deceleration shapes.
    pub shapes: (Shape, Shape),
    /// The interpolation period, s.
    pub period_s: f64,
    /// The move, once planned from the joints where it started.
    pub planned: Option<PtpMove>,
}

impl JointMove {
    /// Plans the move from `from` (the joints where it starts).
    pub fn plan(&self, from: &Axes) -> Result<PtpMove, PlanError> {
        PtpMove::new(
            from,
            &self.target,
            &self.speed,
            &[self.ramps; AXES],
            &[self.shapes; AXES],
            self.period_s,
            true,
        )
    }

    /// Periods it lasts (0 until planned).
    pub fn periods(&self) -> u64 {
        self.planned.as_ref().map_or(0, PtpMove::periods)
    }

    /// The joints after `k` periods.
    pub fn joints_at(&self, k: u64) -> Axes {
        self.planned.as_ref().map_or(self.target, |m| m.position(k))
    }

    /// The group's Cartesian command position after `k` periods: the start until the
    /// joints arrive, then the end (the Cartesian path of a joint move is whatever the
    /// joints make of it; `MCC_GetCurPos` reads it through the forward kinematics).
    pub fn cart_at(&self, k: u64) -> Axes {
        if k >= self.periods() {
            self.cart_end
        } else {
            self.cart_start
        }
    }
}

impl Shared {
    /// The kinematics stage after a tick (see the module's documentation): runs on the
    /// engine thread with no lock held, and holds a group's lock only to read what the
    /// callbacks need and to store what they returned.
    pub(super) fn kinematics_stage(&self) {
        if !self.kinematics_on.load(Ordering::Acquire) {
            return;
        }
        for n in 0..self.group_count() {
            let job = self.nth_group(n).and_then(|mut g| g.kinematics_job());
            let Some(job) = job else { continue };
            let done = job.call();
            if let Some(mut g) = self.nth_group(n) {
                g.kinematics_done(done);
                self.publish(&mut g);
            }
        }
    }
}
