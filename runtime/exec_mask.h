// Every execution-mask operation of the interpreter, in one place (Mesa
// gallivm's lp_exec_mask style). A lane is active when it is live, has not
// discarded, and has not left the innermost loop iteration (break, continue)
// or the innermost call/scope (return):
//
//     exec = entry & alive & ~brk & ~cont & ~ret
//
// where `entry` is the mask the innermost construct started with. Each verb
// saves what it overrides in a frame and restores it when the construct ends.
#pragma once
#include <cstdint>

#include "runtime/interpreter.h"

namespace glslrun::rt {

class ExecMask {
public:
    struct IfFrame {
        LaneMask entry, cond;
    };
    struct LoopFrame {
        LaneMask entry, brk, cont;
    };
    struct CallFrame {
        LaneMask entry, brk, cont, ret;
    };

    void reset(LaneMask live) {
        alive_ = live;
        brk_ = cont_ = ret_ = 0;
        set(live);
    }

    LaneMask active() const { return exec_; }
    bool any() const { return exec_ != 0; }
    bool full() const { return exec_ == kAllLanes; }
    LaneMask alive() const { return alive_; }

    // --- if / else / endif
    IfFrame if_push(LaneMask cond) {
        IfFrame f{exec_, cond};
        set(exec_ & cond);
        return f;
    }
    void if_else(const IfFrame& f) { set(remaining(f.entry & ~f.cond)); }
    void if_pop(const IfFrame& f) { set(remaining(f.entry)); }

    // --- loop { body } continue { alt }
    LoopFrame loop_begin() {
        LoopFrame f{exec_, brk_, cont_};
        brk_ = cont_ = 0;
        return f;
    }
    // Before the continue block: lanes that continued come back.
    void loop_continue_block(const LoopFrame& f) {
        cont_ = 0;
        set(remaining(f.entry));
    }
    // After the continue block: true while some lane still iterates.
    bool loop_iteration_end(const LoopFrame& f) {
        cont_ = 0;
        set(remaining(f.entry));
        return any();
    }
    void loop_end(const LoopFrame& f) {
        brk_ = f.brk;
        cont_ = f.cont;
        set(remaining(f.entry));
    }

    // --- call / scope: Return ends it for the lanes that return.
    CallFrame call_begin() {
        CallFrame f{exec_, brk_, cont_, ret_};
        brk_ = cont_ = ret_ = 0;
        return f;
    }
    void call_end(const CallFrame& f) {
        brk_ = f.brk;
        cont_ = f.cont;
        ret_ = f.ret;
        set(remaining(f.entry));
    }

    // --- lanes leaving
    void do_break() {
        brk_ |= exec_;
        set(0);
    }
    void do_continue() {
        cont_ |= exec_;
        set(0);
    }
    void do_return() {
        ret_ |= exec_;
        set(0);
    }
    void do_discard() {
        alive_ &= ~exec_;
        set(0);
    }

private:
    LaneMask remaining(LaneMask entry) const { return entry & alive_ & ~brk_ & ~cont_ & ~ret_; }
    // Masks change at every branch; per-lane blend words are derived only by
    // the writes that need them (Machine::write).
    void set(LaneMask m) { exec_ = m; }

    LaneMask exec_ = 0, alive_ = 0, brk_ = 0, cont_ = 0, ret_ = 0;
};

}  // namespace glslrun::rt
