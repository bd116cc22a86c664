// The returning fiber switch: Boost 1.74's x86-64 jump_fcontext, ending with a return instead
// of an indirect jump; and which switch the build uses.
//
// Boost's version loads the resumed context's return address and jumps to it. The call into
// the switch, though, pushed an entry on the processor's return-stack predictor that no return
// pops, so after every switch each return of the resumed process on its way back to its own
// code (out of the switch, out of Kernel::block, ...) is predicted with the entry of the
// frame below: all of them miss. Returning instead pops that entry and keeps the predictor in step;
// since processes suspend at the same few call sites, the predictions mostly hold.
//
// The frame is Boost's, byte for byte (MXCSR and x87 control word, r12-r15, rbx, rbp, return
// address), so a context suspended here can be resumed, unwound or ended by Boost's own
// jump_fcontext and ontop_fcontext, and the other way round.

#include "marsokhod/emulator/fiber_switch.hpp"

#include "fiber.hpp"

#include <string_view>

#if !MARSOKHOD_HAVE_RETURNING_SWITCH && !defined(BOOST_USE_UCONTEXT) &&                            \
    !defined(BOOST_USE_WINFIB) && defined(__x86_64__) && defined(__ELF__)
#pragma message("the returning fiber switch is written for Boost 1.74.0 (BOOST_VERSION 107400); "  \
                "this Boost switches with its own fiber::resume")
#endif

namespace marsokhod::emulator {

std::string_view fiber_switch_name() {
  return MARSOKHOD_RETURNING_SWITCH ? "returning" : "boost";
}

// The build system works out the same choice (emulator/CMakeLists.txt); they must agree.
#ifdef MARSOKHOD_FIBER_SWITCH_EXPECTED
static_assert(std::string_view(MARSOKHOD_FIBER_SWITCH_EXPECTED) ==
                  (MARSOKHOD_RETURNING_SWITCH ? "returning" : "boost"),
              "the fiber switch compiled in is not the one CMake selected");
#endif

} // namespace marsokhod::emulator

#if MARSOKHOD_HAVE_RETURNING_SWITCH

asm(R"(
    .pushsection .text
    .globl marsokhod_jump_fcontext
    .hidden marsokhod_jump_fcontext
    .type marsokhod_jump_fcontext, @function
    .p2align 4
marsokhod_jump_fcontext:
    leaq    -0x38(%rsp), %rsp
    stmxcsr (%rsp)
    fnstcw  0x4(%rsp)
    movq    %r12, 0x8(%rsp)
    movq    %r13, 0x10(%rsp)
    movq    %r14, 0x18(%rsp)
    movq    %r15, 0x20(%rsp)
    movq    %rbx, 0x28(%rsp)
    movq    %rbp, 0x30(%rsp)
    movq    %rsp, %rax
    movq    %rdi, %rsp
    ldmxcsr (%rsp)
    fldcw   0x4(%rsp)
    movq    0x8(%rsp), %r12
    movq    0x10(%rsp), %r13
    movq    0x18(%rsp), %r14
    movq    0x20(%rsp), %r15
    movq    0x28(%rsp), %rbx
    movq    0x30(%rsp), %rbp
    leaq    0x38(%rsp), %rsp
    movq    %rsi, %rdx
    movq    %rax, %rdi
    ret
    .size marsokhod_jump_fcontext, .-marsokhod_jump_fcontext
    .popsection
)");

#endif
