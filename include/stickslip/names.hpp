// One name table per enum: EnumNames<E>::kTable lists every value with its
// printed name (the name written to TSV files and shown by the apps), and
// Name / FromName read it both ways. A header that declares an enum
// specialises EnumNames beside it; no enum-to-string switch elsewhere.
#pragma once

#include <cstddef>
#include <string_view>

namespace stickslip {

template <typename E>
struct NamedValue {
  E value;
  const char* name;
};

/// Specialise with `static constexpr NamedValue<E> kTable[] = {...};`.
template <typename E>
struct EnumNames;

/// The printed name of e ("?" if the table lacks it: a missing entry).
template <typename E>
const char* Name(E e) {
  for (const NamedValue<E>& nv : EnumNames<E>::kTable)
    if (nv.value == e) return nv.name;
  return "?";
}

/// The value named `name`; false if no value has that name.
template <typename E>
bool FromName(std::string_view name, E* e) {
  for (const NamedValue<E>& nv : EnumNames<E>::kTable)
    if (name == nv.name) {
      *e = nv.value;
      return true;
    }
  return false;
}

/// Number of named values (for loops over all of them).
template <typename E>
constexpr std::size_t NameCount() {
  return sizeof(EnumNames<E>::kTable) / sizeof(EnumNames<E>::kTable[0]);
}

}  // namespace stickslip
