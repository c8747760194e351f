// polyDEM: the one exception type. It carries the input file and the entry
// that were wrong so that front ends (demFoam) can report them FatalIOError-style.
#pragma once

#include <stdexcept>
#include <string>

namespace polydem
{

class Error : public std::runtime_error
{
public:
    Error(const std::string& message, std::string file = "", std::string entry = "")
        : std::runtime_error(compose(message, file, entry)), message_(message),
          file_(std::move(file)), entry_(std::move(entry))
    {
    }

    const std::string& message() const { return message_; }
    const std::string& file() const { return file_; }
    const std::string& entry() const { return entry_; }

private:
    static std::string compose(const std::string& m, const std::string& f, const std::string& e)
    {
        std::string s;
        if (!f.empty()) s += "file " + f + ": ";
        if (!e.empty()) s += "entry '" + e + "': ";
        return s + m;
    }

    std::string message_, file_, entry_;
};

} // namespace polydem
