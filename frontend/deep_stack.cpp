#include "frontend/deep_stack.h"

#include <pthread.h>

namespace glslrun::frontend {

namespace {

void* call(void* fn) {
    (*static_cast<const std::function<void()>*>(fn))();
    return nullptr;
}

}  // namespace

void run_on_deep_stack(const std::function<void()>& fn) {
    pthread_attr_t attr;
    pthread_t thread;
    bool started = pthread_attr_init(&attr) == 0 && pthread_attr_setstacksize(&attr, kCompileStackBytes) == 0 &&
                   pthread_create(&thread, &attr, call, const_cast<std::function<void()>*>(&fn)) == 0;
    pthread_attr_destroy(&attr);
    if (started) pthread_join(thread, nullptr);
    else fn();
}

}  // namespace glslrun::frontend
