// run_program.cpp — exceptions to exit codes, most specific first.
#include "app/run_program.h"

#include "app/scene_setup.h"
#include "common/errors.h"
#include "common/phase_log.h"

namespace vkpt {

int runProgram(const std::string& program, const std::function<int()>& body) {
    // The phase log's clock starts here, so that the report's "time in all" is the program's.
    processPhases();
    try {
        return body();
    } catch (const InputError& error) {
        return reportFailure(program, error, 1);
    } catch (const DeviceError& error) {
        return reportFailure(program, error, 2);
    } catch (const std::exception& error) {
        return reportFailure(program, error, 3);
    }
}

} // namespace vkpt
