// Hand-offs between threads that ThreadSanitizer cannot see by itself.
//
// oneTBB orders the bodies it runs (a serial pipeline filter runs one item at a time; an item passes from one
// filter to the next; a parallel_for returns after its bodies), but it does so inside libtbb.so, which
// Debian does not build with -fsanitize=thread. TSan then reports these ordered accesses as data races.
// HandOffRelease(p) after the last write that a later body relies on and HandOffAcquire(p) before that
// body's first read tell TSan about exactly the ordering oneTBB guarantees (the same address on both sides).
// Without -fsanitize=thread both are no-ops.
#pragma once

#if defined(__SANITIZE_THREAD__)
#define VIGIL_TSAN 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define VIGIL_TSAN 1
#endif
#endif

#ifdef VIGIL_TSAN
extern "C" void __tsan_acquire(void* addr);
extern "C" void __tsan_release(void* addr);
#endif

namespace vigil {

inline void HandOffRelease([[maybe_unused]] const void* sync) {
#ifdef VIGIL_TSAN
  __tsan_release(const_cast<void*>(sync));
#endif
}

inline void HandOffAcquire([[maybe_unused]] const void* sync) {
#ifdef VIGIL_TSAN
  __tsan_acquire(const_cast<void*>(sync));
#endif
}

}  // namespace vigil
