//! Robot kinematics of the virtual card (`MCC_SetKinematicTrans`): the program's forward
//! and inverse kinematics as a group holds them, their extension buffer, and what a
//! registration made before the card starts carries. Where registrations wait for the
//! next init is the library's business (its `engine::kinematics`).
//!
//! # How a kinematic group runs
//!
//! As in the vendor's library, the group's channels carry joints and everything a program
//! reads of the group is the joints': `MCC_GetCurPos`, `MCC_GetPulsePos`, the speeds.
//! Point-to-point moves (`MCC_PtP_V6`, `MCC_PtP`, `MCC_SyncPtP`) move the joints;
//! path commands (lines, arcs, circles, helices, the V6 curves, custom motion) move the
//! tool in Cartesian space (X, Y, Z, RX, RY, RZ and two aux axes in the axes X..B).
//! [`crate::engine::group::kinematics`] keeps the joints and which space the group's
//! planner is in; it switches between the two when the next command needs the other
//! one and nothing runs. The user's callbacks never run with a library lock held, so
//! they may call any `MCC_*` function:
//!
//! 1. Tick k (`super::tick`): the group moves as any group does; in joint space its
//!    position is the joints, in Cartesian space the joints computed after tick k−1 are
//!    applied. The channels get the joints' pulses.
//! 2. After tick k, with every lock released (`Shared::kinematics_stage`, called by
//!    the engine thread's loop): for each kinematic group, read under its lock what the
//!    callbacks need (the Cartesian point of tick k, or the joints to convert when the
//!    planner changes space), release the lock, call them, take the lock again and store
//!    the result.
//!
//! So in Cartesian space the joints follow the planner one interpolation period later,
//! and the group reports `GMS_STOP` only once the joints of the planner's last point are
//! out. Everything happens on the engine thread in tick order: the same under the fast,
//! stepped and realtime clocks. A `FALSE` (or a non-finite joint) from the inverse
//! kinematics stops the group with error record 0xF106: the joints stay where they were
//! (no jump) and the Cartesian position goes back to the last point they reached.

use crate::config::AXES;
use crate::planner::Axes;
use crate::vendor::{BOOL, DWORD, FWDKINEFUN, INIT_EXTENSION, INVKINEFUN};
use std::ffi::c_void;
use std::os::raw::c_int;
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

/// A group's kinematics as the program registers them before the card starts
/// (`MCC_SetKinematicTrans`): checked (both callbacks given, the extension's size at most
/// [`MAX_EXTENSION_BYTES`]) and kept until the next successful init applies them.
#[derive(Debug, Clone, Copy)]
pub struct Registration {
    /// Forward kinematics (never NULL).
    pub fwd: FWDKINEFUN,
    /// Inverse kinematics (never NULL).
    pub inv: INVKINEFUN,
    /// Bytes of the extension buffer.
    pub ext_size: u64,
    /// The extension's initialiser (may be NULL).
    pub init: INIT_EXTENSION,
}
