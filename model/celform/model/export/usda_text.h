// The text of a USDA layer (the USD text format, Pixar's "USD File Formats" and the Crate-free
// .usda grammar) built in one reused buffer: numbers in their shortest round-trip form
// (std::to_chars, so a reader gets back the very float written), identifiers, tuples and arrays.
// The USD export (export_usda.cpp) fills a buffer per frame and writes it at once.
#pragma once

#include <charconv>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace celform::model::exporting {

class UsdaText {
public:
    /// Longest text of one number (shortest round-trip double, sign and exponent).
    static constexpr std::size_t kNumberChars = 32;

    /// Makes room for at least bytes more without moving the text (call before a big array).
    void reserve(std::size_t bytes)
    {
        if (m_size + bytes > m_bytes.size())
            m_bytes.resize(m_size + bytes);
    }
    void clear() { m_size = 0; }
    [[nodiscard]] const char* data() const { return m_bytes.data(); }
    [[nodiscard]] std::size_t size() const { return m_size; }

    UsdaText& text(std::string_view s)
    {
        reserve(s.size());
        s.copy(m_bytes.data() + m_size, s.size());
        m_size += s.size();
        return *this;
    }
    UsdaText& operator<<(std::string_view s) { return text(s); }
    UsdaText& operator<<(char c)
    {
        reserve(1);
        m_bytes[m_size++] = c;
        return *this;
    }
    UsdaText& operator<<(float v) { return number(v); }
    UsdaText& operator<<(double v) { return number(v); }
    UsdaText& operator<<(int v) { return number(v); }
    UsdaText& operator<<(long v) { return number(v); }

    /// A quoted string with ", \ and control characters escaped.
    UsdaText& quoted(std::string_view s);

    /// (a, b, c): a tuple of n numbers.
    template <typename T> UsdaText& tuple(const T* values, int n)
    {
        reserve(std::size_t(n) * (kNumberChars + 2) + 2);
        put('(');
        for (int i = 0; i < n; ++i) {
            if (i > 0)
                putText(", ");
            putNumber(values[i]);
        }
        put(')');
        return *this;
    }

    /// [(x, y, z), ...]: rows of a row-major array of count tuples of n numbers; one reserve,
    /// then no checks (the hot loop of the export).
    template <typename T> UsdaText& tuples(const T* values, std::size_t count, int n)
    {
        reserve(count * (std::size_t(n) * (kNumberChars + 2) + 4) + 2);
        put('[');
        for (std::size_t r = 0; r < count; ++r) {
            if (r > 0)
                putText(", ");
            put('(');
            const T* row = values + r * std::size_t(n);
            for (int i = 0; i < n; ++i) {
                if (i > 0)
                    putText(", ");
                putNumber(row[i]);
            }
            put(')');
        }
        put(']');
        return *this;
    }

    /// [a, b, ...]: count numbers.
    template <typename T> UsdaText& list(const T* values, std::size_t count)
    {
        reserve(count * (kNumberChars + 2) + 2);
        put('[');
        for (std::size_t i = 0; i < count; ++i) {
            if (i > 0)
                putText(", ");
            putNumber(values[i]);
        }
        put(']');
        return *this;
    }

private:
    template <typename T> UsdaText& number(T v)
    {
        reserve(kNumberChars);
        putNumber(v);
        return *this;
    }
    template <typename T> void putNumber(T v)
    {
        char* at = m_bytes.data() + m_size;
        m_size = std::size_t(std::to_chars(at, at + kNumberChars, v).ptr - m_bytes.data());
    }
    void put(char c) { m_bytes[m_size++] = c; }
    void putText(std::string_view s)
    {
        s.copy(m_bytes.data() + m_size, s.size());
        m_size += s.size();
    }

    std::vector<char> m_bytes;
    std::size_t m_size = 0;
};

/// A USD identifier made of a name: characters outside [A-Za-z0-9_] become _, and a leading
/// digit (or an empty name) gets a _ before it.
std::string usdIdentifier(std::string_view name);

} // namespace celform::model::exporting
