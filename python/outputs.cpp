#include "python/outputs.h"

#include <mutex>
#include <thread>

#include "protocol/output_file.h"

namespace fb89::python {

namespace {

std::mutex g_turn;         // held while a call's batch is open
std::thread::id g_holder;  // the thread holding it (guarded by g_holder_mutex)
std::mutex g_holder_mutex;

}  // namespace

void with_outputs(const std::function<void()>& work) {
    {
        std::lock_guard lock(g_holder_mutex);
        if (g_holder == std::this_thread::get_id())
            throw std::logic_error(
                "a call that writes files cannot be made while another one on the same thread "
                "(whose progress callback this is) has its outputs open");
    }
    std::lock_guard turn(g_turn);
    {
        std::lock_guard lock(g_holder_mutex);
        g_holder = std::this_thread::get_id();
    }
    struct Release {
        ~Release() {
            std::lock_guard lock(g_holder_mutex);
            g_holder = std::thread::id();
        }
    } release;
    protocol::OutputBatch batch;
    work();
    file_work([&] { batch.publish(); });
}

}  // namespace fb89::python
