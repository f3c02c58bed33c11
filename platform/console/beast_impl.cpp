/// @file beast_impl.cpp
/// @brief Asio's and Beast's own compiled parts, once for every file that uses them (BOOST_ASIO_SEPARATE_COMPILATION,
///        BOOST_BEAST_SEPARATE_COMPILATION): the server and the tests' client then compile only what they use.
#include <boost/asio/impl/src.hpp>
#include <boost/asio/ssl/impl/src.hpp>
#include <boost/beast/src.hpp>
