//! A minimal emulator: the FX5 clock addition TADD as a pure function. It knows nothing of
//! plcvec; `tests/plcvec.rs` is the glue that runs it on the vectors.
#![forbid(unsafe_code)]

const DAY: i64 = 24 * 3600;

/// Error 3405H: a value of (s1) or (s2) is out of range.
pub const ERR_VALUE_RANGE: u16 = 0x3405;

/// What TADD stores: the time in (d), and the carry and zero flags.
#[derive(Debug, PartialEq, Eq)]
pub struct Sum {
    /// hour, minute, second.
    pub time: [u16; 3],
    /// Past 24:00:00 (SM700, SM8022).
    pub carry: bool,
    /// 0:00:00 (SM8020).
    pub zero: bool,
}

/// (s1) + (s2), each hour/minute/second in "16-bit signed binary"; an error code when a value
/// is out of range.
pub fn tadd(s1: [u16; 3], s2: [u16; 3]) -> Result<Sum, u16> {
    let hms = |t: [u16; 3]| t.map(|w| i64::from(w as i16));
    let (a, b) = (hms(s1), hms(s2));
    let valid = |t: [i64; 3]| (0..=23).contains(&t[0]) && (0..=59).contains(&t[1]) && (0..=59).contains(&t[2]);
    if !valid(a) || !valid(b) {
        return Err(ERR_VALUE_RANGE);
    }
    let sum = (a[0] + b[0]) * 3600 + (a[1] + b[1]) * 60 + a[2] + b[2];
    let t = sum % DAY;
    Ok(Sum { time: [t / 3600, t / 60 % 60, t % 60].map(|v| v as u16), carry: sum >= DAY, zero: t == 0 })
}
