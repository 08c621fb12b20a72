#pragma once

#include <stdexcept>

namespace cscd {

// Input the core cannot work with (a shape, an option, an index); the message is written for the user.
class InputError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

} // namespace cscd
