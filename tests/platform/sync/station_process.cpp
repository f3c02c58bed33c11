/// @file station_process.cpp
/// @brief fork + exec of a station, its exit with a deadline, its logs.
#include "station_process.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "tests/file_text.h"

namespace lungar::testing {

StationProcess::StationProcess(const std::string& program, const std::vector<std::string>& args,
                               const std::filesystem::path& log_prefix)
    : out_(log_prefix.string() + ".out"), err_(log_prefix.string() + ".err") {
  std::vector<char*> argv;
  argv.push_back(const_cast<char*>(program.c_str()));
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_ = fork();
  if (pid_ == 0) {
    const int o = open(out_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int e = open(err_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(o, 1);
    dup2(e, 2);
    execv(program.c_str(), argv.data());
    _exit(127);
  }
}

StationProcess::~StationProcess() {
  if (pid_ > 0) {
    kill_now();
    waitpid(pid_, nullptr, 0);
  }
}

int StationProcess::wait(double timeout_s) {
  if (pid_ <= 0) return -1;
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < until) {
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return -1;
}

bool StationProcess::wait_for(const std::string& text, double timeout_s) const {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < until) {
    if (err().find(text) != std::string::npos) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

void StationProcess::kill_now() {
  if (pid_ > 0) ::kill(pid_, SIGKILL);
}

int StationProcess::stop(double timeout_s) {
  if (pid_ > 0) ::kill(pid_, SIGTERM);
  return wait(timeout_s);
}

std::string StationProcess::err() const { return file_text(err_); }
std::string StationProcess::out() const { return file_text(out_); }

}  // namespace lungar::testing
