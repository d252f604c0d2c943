//! Synchronous moves and chains of them (§4.16, §4.17, §6.12), and the chained-move
//! buffer a failed call may leave behind.

use std::os::raw::c_int;

use super::call::{as_u32, dir, range, with_state, Check, State};
use super::*;
use ::mc3b::client::{Client, ClientError, Transport};
use ::mc3b::codec::{Command, ErrorCode};

fn sync_check(s: [c_int; 3], d: [c_int; 3]) -> Check {
    for i in 0..3 {
        range(s[i], 0, c_int::MAX)?;
        dir(d[i])?;
    }
    Ok(())
}

fn sync_cmd(id: u8, s: [c_int; 3], d: [c_int; 3], execute: bool) -> Result<Command, c_int> {
    Ok(Command::SyncMove {
        id,
        steps: [as_u32(s[0])?, as_u32(s[1])?, as_u32(s[2])?],
        directions: [as_u32(d[0])?, as_u32(d[1])?, as_u32(d[2])?],
        execute: Some(u32::from(execute)),
    })
}

/// The body of [`crate::ffi::mcl::mcl_synchronous_move_motor`] (its documentation says what it does):
/// a §4 status.
#[allow(clippy::too_many_arguments)]
pub fn synchronous_move_motor(
    controller_id: c_int,
    motor_0_steps: c_int,
    motor_0_direction: c_int,
    motor_1_steps: c_int,
    motor_1_direction: c_int,
    motor_2_steps: c_int,
    motor_2_direction: c_int,
    execute: bool,
) -> c_int {
    let s = [motor_0_steps, motor_1_steps, motor_2_steps];
    let d = [motor_0_direction, motor_1_direction, motor_2_direction];
    let mut built = None;
    let code = with_state(
        controller_id,
        || sync_check(s, d),
        |state, id| match sync_cmd(id, s, d, execute) {
            Ok(cmd) => with_clean_buffer(state, id, |client| client.command(&cmd)),
            Err(code) => {
                built = Some(code);
                Ok(())
            }
        },
    );
    built.unwrap_or(code)
}

/// Runs `f` (which sends `Y` commands) after discarding a chained-move buffer left
/// by a failed call; if `f` fails, the buffer is marked for discarding (the `mcl`
/// module's docs).
fn with_clean_buffer(
    state: &mut State,
    id: u8,
    f: impl FnOnce(&mut Client<Box<dyn Transport + Send>>) -> Result<(), ClientError>,
) -> Result<(), ClientError> {
    if state.chain_dirty {
        state.client.command(&Command::SyncMove {
            id,
            steps: [0; 3],
            directions: [0; 3],
            execute: None,
        })?;
        state.chain_dirty = false;
    }
    let r = f(&mut state.client);
    if r.is_err() {
        state.chain_dirty = true;
    }
    r
}

/// The body of [`crate::ffi::mcl::mcl_chained_synchronous_move_motor`] (its documentation says what it does):
/// a §4 status.
///
/// # Safety
/// Each pointer must be null or valid for reading `number_of_moves` ints.
#[allow(clippy::too_many_arguments)]
pub unsafe fn chained_synchronous_move_motor(
    controller_id: c_int,
    number_of_moves: c_int,
    motor_0_steps: *const c_int,
    motor_0_direction: *const c_int,
    motor_1_steps: *const c_int,
    motor_1_direction: *const c_int,
    motor_2_steps: *const c_int,
    motor_2_direction: *const c_int,
) -> c_int {
    let ptrs = [
        motor_0_steps,
        motor_0_direction,
        motor_1_steps,
        motor_1_direction,
        motor_2_steps,
        motor_2_direction,
    ];
    if !is_initialized() {
        return MCL_NOT_INITIALIZED_ERROR;
    }
    // SAFETY: the pointers are the caller's, under this function's contract.
    let moves = match unsafe { read_moves(number_of_moves, ptrs) } {
        Ok(m) => m,
        Err(code) => return code,
    };
    let mut build_err = None;
    let code = with_state(
        controller_id,
        || Ok(()),
        |state, id| {
            let cmds: Result<Vec<Command>, c_int> = moves
                .iter()
                .enumerate()
                .map(|(k, (s, d))| sync_cmd(id, *s, *d, k + 1 == moves.len()))
                .collect();
            let cmds = match cmds {
                Ok(c) => c,
                Err(c) => {
                    build_err = Some(c);
                    return Ok(());
                }
            };
            // §4.16: all three motors idle, or nothing is stored.
            for m in 0..3 {
                let idle = state.client.query_status(id, m).map(|st| !st.running);
                match idle {
                    Ok(true) => {}
                    Ok(false) => {
                        state.chain_dirty = true;
                        return Err(ClientError::Device(ErrorCode::MotorRunning));
                    }
                    Err(e) => {
                        state.chain_dirty = true;
                        return Err(e);
                    }
                }
            }
            with_clean_buffer(state, id, |client| {
                for cmd in &cmds {
                    client.command(cmd)?;
                }
                Ok(())
            })
        },
    );
    build_err.unwrap_or(code)
}

type Move3 = ([c_int; 3], [c_int; 3]);

/// Read and range-check the six arrays of a chained move.
///
/// # Safety
/// Each non-null pointer must be valid for reading `number_of_moves` ints.
unsafe fn read_moves(number_of_moves: c_int, ptrs: [*const c_int; 6]) -> Result<Vec<Move3>, c_int> {
    range(number_of_moves, 1, MCL_MAX_CHAINED_MOVES)?;
    if ptrs.iter().any(|p| p.is_null()) {
        return Err(MCL_PARAMETER_OUT_OF_RANGE_ERROR);
    }
    let n = usize::try_from(number_of_moves).map_err(|_| MCL_PARAMETER_OUT_OF_RANGE_ERROR)?;
    let mut arrays: Vec<&[c_int]> = Vec::with_capacity(6);
    for p in ptrs {
        // SAFETY: non-null (checked above) and valid for `n` reads per the
        // caller's contract; n is 1..=100.
        arrays.push(unsafe { std::slice::from_raw_parts(p, n) });
    }
    let mut moves = Vec::with_capacity(n);
    for k in 0..n {
        let v = |a: usize| arrays.get(a).and_then(|s| s.get(k)).copied().unwrap_or(-1);
        let s = [v(0), v(2), v(4)];
        let d = [v(1), v(3), v(5)];
        sync_check(s, d)?;
        moves.push((s, d));
    }
    Ok(moves)
}
