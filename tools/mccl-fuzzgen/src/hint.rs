//! The value class each parameter or field draws from, and how many elements a pointer
//! parameter points to: the fuzzer's knowledge of the vendor's argument names.

use crate::view::{Base, Decl, Prim};

/// The value class a parameter or field draws from (`FZ_H_*` in fuzz_rt.h), from the
/// function and the parameter's name. Unknown names draw from the whole type.
pub fn hint(func: &str, name: &str, p: Prim) -> &'static str {
    let real = matches!(p, Prim::F32 | Prim::F64);
    let has = |s: &str| name.contains(s);
    if func == "MCC_TimeDelay" {
        return "FZ_H_TIMEDELAY"; // bounded: the calling thread waits this long
    }
    if has("QueueSize") || func.contains("QueueSize") || has("StockNum") {
        return "FZ_H_QSIZE"; // capped: a size is reserved up front
    }
    if name == "com_port" {
        return "FZ_H_COMPORT";
    }
    if func == "MCC_DelayMotion" {
        return "FZ_H_DELAY";
    }
    if has("InterpolateTime") {
        return "FZ_H_INTERP";
    }
    if p == Prim::Char {
        if has("Axis") {
            return "FZ_H_AXISCHAR";
        }
        if has("AccType") || has("DecType") {
            return "FZ_H_ACCTYPE";
        }
        return "FZ_H_ANY";
    }
    if real {
        if has("Voltage") || has("fValue") || has("Input") {
            return "FZ_H_VOLT";
        }
        if has("Pitch") || has("GearRat") {
            return "FZ_H_RATIO";
        }
        if has("Speed") || has("Ratio") || has("Rate") || has("Feed") || has("Vel") {
            return "FZ_H_SPEED";
        }
        if has("Time") {
            return "FZ_H_TIMEMS";
        }
        if has("Limit") || has("Tolerance") {
            return "FZ_H_LIMIT";
        }
        return "FZ_H_POS";
    }
    if has("Group") {
        return "FZ_H_GROUP";
    }
    if has("CardNo") {
        return "FZ_H_CARDNO";
    }
    if has("CardType") {
        return "FZ_H_CARDTYPE";
    }
    if has("Card") {
        return "FZ_H_CARD";
    }
    if has("MapToCh") {
        return "FZ_H_MAPCH";
    }
    if has("Channel")
        || has("Point")
        || has("DigitalInput")
        || name == "wAxis"
        || name == "wCh"
        || name == "motor_id"
    {
        return "FZ_H_CHANNEL";
    }
    if name == "wSet" {
        return "FZ_H_SET";
    }
    if has("Slave") || has("Port") {
        return "FZ_H_SLAVE";
    }
    if has("Order") {
        return "FZ_H_ORDER";
    }
    if has("Mask") {
        return "FZ_H_MASK";
    }
    if has("CirDir") || has("Dir") || has("direction") {
        return "FZ_H_DIR";
    }
    if p == Prim::Bool
        || (name.starts_with('b') && name.chars().nth(1).is_some_and(|c| c.is_ascii_uppercase()))
    {
        return "FZ_H_BOOL";
    }
    if has("Level") || has("Sensor") || has("Output") || has("controller") {
        return "FZ_H_SMALL";
    }
    if has("PPR") || has("RPM") {
        return "FZ_H_PPR";
    }
    if has("Mode") || has("Type") || has("Rate") || has("Source") || has("Enable") {
        return "FZ_H_SMALL";
    }
    if has("Time") || has("Period") || name == "dwValue" {
        return "FZ_H_PERIOD";
    }
    "FZ_H_ANY"
}

/// Elements a pointer parameter points to (one unless its role says otherwise).
pub fn count(d: &Decl) -> &'static str {
    if d.name.contains("CardConfig") {
        "MAX_CARD_NUM" // an array of wCardNo cards, at most MAX_CARD_NUM
    } else if d.name.starts_with("str") && matches!(d.base, Base::Prim(Prim::Char)) {
        "5" // MCC_GetVersion: the library documents 5 bytes ("6.00" and its NUL)
    } else if d.is_const {
        "128" // an input array (mcl_chained_synchronous_move_motor: at most 100 moves)
    } else {
        "1"
    }
}
