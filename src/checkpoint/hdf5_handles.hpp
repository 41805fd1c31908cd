// Internal to src/checkpoint: RAII ownership of HDF5 identifiers (hid_t), and HDF5's error
// reporting turned from printed stack traces into strings for our own exceptions.
#pragma once
#include <string>
#include <utility>

#include <hdf5.h>

namespace shapevo::h5 {

/// Owns one hid_t and closes it with the matching H5?close when it goes away.
class Handle {
public:
    using Closer = herr_t (*)(hid_t);
    Handle() = default;
    Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, H5I_INVALID_HID)), closer_(o.closer_) {}
    Handle& operator=(Handle&& o) noexcept {
        if (this != &o) {
            reset();
            id_ = std::exchange(o.id_, H5I_INVALID_HID);
            closer_ = o.closer_;
        }
        return *this;
    }
    ~Handle() { reset(); }

    hid_t get() const { return id_; }
    bool valid() const { return id_ >= 0; }
    /// Close now and report whether closing succeeded (a file's close can fail on a full disk).
    bool close() {
        if (id_ < 0) return true;
        const herr_t status = closer_(std::exchange(id_, H5I_INVALID_HID));
        return status >= 0;
    }
    void reset() { close(); }

private:
    hid_t id_ = H5I_INVALID_HID;
    Closer closer_ = nullptr;
};

inline Handle fileHandle(hid_t id) { return {id, H5Fclose}; }
inline Handle groupHandle(hid_t id) { return {id, H5Gclose}; }
inline Handle datasetHandle(hid_t id) { return {id, H5Dclose}; }
inline Handle spaceHandle(hid_t id) { return {id, H5Sclose}; }
inline Handle typeHandle(hid_t id) { return {id, H5Tclose}; }
inline Handle attributeHandle(hid_t id) { return {id, H5Aclose}; }
inline Handle plistHandle(hid_t id) { return {id, H5Pclose}; }

/// Turn off HDF5's automatic printing of error stacks for the calling thread (this libhdf5 is
/// built thread-safe, where every thread has its own default error stack and its own setting),
/// so failures reach the user once, as our exception, not as a page of library internals.
/// Cheap after the first call on a thread.
void silenceErrorPrinting();

/// The innermost (most specific) message on the calling thread's HDF5 error stack, e.g.
/// "unable to open file: ... error message = 'No such file or directory'"; then clears it.
/// "HDF5 call failed" if the stack is empty.
std::string takeErrorMessage();

}  // namespace shapevo::h5
