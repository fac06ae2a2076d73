//! The AVX2 build of a pass, written once: [`with_avx2`] runs a closure compiled for AVX2 where
//! the CPU has it and as it is elsewhere. The passes it serves do the same IEEE operations either
//! way (no fused multiply-adds, fixed summation order), so both builds give the same numbers.

/// Runs `f` compiled for AVX2 if the CPU has it, else the baseline build. Mark the closure
/// `#[inline(always)]` so that its body is compiled inside the AVX2 function.
#[inline(always)]
pub fn with_avx2<R>(f: impl FnOnce() -> R) -> R {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: AVX2 is available (checked just above).
        return unsafe { avx2(f) };
    }
    f()
}

/// [`with_avx2`]'s AVX2 build.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn avx2<R>(f: impl FnOnce() -> R) -> R {
    f()
}
