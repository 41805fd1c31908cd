// takeOverLauncherLoss: a PMIx event handler for PMIX_ERR_LOST_CONNECTION, registered to run
// first; it sets a flag and tells PMIx the event is handled (PMIX_EVENT_ACTION_COMPLETE), which
// keeps OpenMPI's own handler (registered for every event) from aborting the rank.
#include "island/launcher_link.hpp"

#include <atomic>

#ifdef SHAPEVO_WITH_PMIX
#include <pmix.h>
#endif

namespace shapevo {

namespace {
// PMIx's handler is a C callback without user data: the flag it sets is the process's, as PMIx is.
std::atomic<bool> gLinkLost{false};

#ifdef SHAPEVO_WITH_PMIX
void onLostConnection(size_t, pmix_status_t, const pmix_proc_t*, pmix_info_t[], size_t, pmix_info_t*, size_t,
                      pmix_event_notification_cbfunc_fn_t done, void* doneData) {
    gLinkLost.store(true);
    if (done) done(PMIX_EVENT_ACTION_COMPLETE, nullptr, 0, nullptr, nullptr, doneData);
}
#endif
}  // namespace

bool takeOverLauncherLoss() {
#ifdef SHAPEVO_WITH_PMIX
    if (!PMIx_Initialized()) return false;
    pmix_status_t code = PMIX_ERR_LOST_CONNECTION;
    pmix_info_t first;
    PMIX_INFO_CONSTRUCT(&first);
    bool yes = true;
    PMIx_Info_load(&first, PMIX_EVENT_HDLR_FIRST, &yes, PMIX_BOOL);
    // Without a completion callback the registration is blocking and returns the handler's id.
    const pmix_status_t id = PMIx_Register_event_handler(&code, 1, &first, 1, onLostConnection, nullptr, nullptr);
    PMIX_INFO_DESTRUCT(&first);
    return id >= 0;
#else
    return false;
#endif
}

bool launcherLinkLost() { return gLinkLost.load(); }

}  // namespace shapevo
