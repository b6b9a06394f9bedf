/* volk_impl.c — the volk meta-loader (Debian ships it as source), compiled without vkpt's
   warning flags because it is not our code. */
#include <volk.c>
