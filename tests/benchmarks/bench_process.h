// Whole processes for the benchmarks that time `celform` as a farm or a shell runs it: fork, exec
// and wait4, with the output on /dev/null.
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace celform::bench {

struct Finished {
    double seconds = 0;
    double peakRssMb = 0;
    int status = -1;
};

/// Runs a program to its end with standard output and error on /dev/null.
inline Finished runProcess(const std::vector<std::string>& args)
{
    std::vector<char*> argv;
    for (const std::string& a : args)
        argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = fork();
    if (pid == 0) {
        const int null = open("/dev/null", O_WRONLY);
        dup2(null, STDOUT_FILENO);
        dup2(null, STDERR_FILENO);
        execv(argv[0], argv.data());
        _exit(127);
    }
    Finished f;
    rusage usage{};
    if (pid < 0 || wait4(pid, &f.status, 0, &usage) != pid)
        return f;
    f.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    f.peakRssMb = double(usage.ru_maxrss) / 1024.0; // kilobytes on Linux
    return f;
}

} // namespace celform::bench
