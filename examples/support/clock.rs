//! Clocks and medians for the timing examples.

/// struct timespec of Linux (64-bit).
#[repr(C)]
struct Timespec {
    sec: i64,
    nsec: i64,
}

unsafe extern "C" {
    fn clock_gettime(clock: i32, out: *mut Timespec) -> i32;
}

/// CPU time of this thread in seconds (CLOCK_THREAD_CPUTIME_ID = 3 on Linux; finer than
/// /proc/thread-self/schedstat, which only advances at scheduler ticks).
pub fn cpu_seconds() -> f64 {
    let mut t = Timespec { sec: 0, nsec: 0 };
    // SAFETY: clock_gettime writes one timespec to a valid pointer.
    let rc = unsafe { clock_gettime(3, &mut t) };
    assert_eq!(rc, 0, "clock_gettime");
    t.sec as f64 + 1e-9 * t.nsec as f64
}

/// The median (the mean of the middle two for an even count).
pub fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

/// The median time in seconds, by `now` (a clock in seconds), of repeated calls of f after a
/// first one (at least 5, then until `budget` seconds have passed or `most` calls), and the
/// last call's result.
pub fn repeated<R>(now: impl Fn() -> f64, budget: f64, most: usize, f: impl Fn() -> R) -> (f64, R) {
    let mut times = Vec::new();
    let start = now();
    let mut last = f();
    while times.len() < 5 || (now() - start < budget && times.len() < most) {
        let t = now();
        last = f();
        times.push(now() - t);
    }
    (median(times), last)
}
