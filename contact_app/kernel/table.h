// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace contact_app {

/// Piecewise-linear table y(x) (Kratos Table<double,double>): rows sorted by x, linear
/// interpolation inside, linear extrapolation from the end segments outside.
class Table {
public:
    Table() = default;
    Table(std::string input_variable, std::string output_variable)
        : mInputVariable(std::move(input_variable)), mOutputVariable(std::move(output_variable)) {}

    /// Inserts a row keeping the rows sorted by x. @throws InputError for a repeated x.
    void PushBack(double x, double y);
    /// @throws InputError on an empty table.
    double GetValue(double x) const;
    /// dy/dx of the segment containing @p x.
    double GetDerivative(double x) const;
    std::size_t Size() const { return mRows.size(); }
    const std::vector<std::pair<double, double>>& Data() const { return mRows; }
    const std::string& InputVariable() const { return mInputVariable; }
    const std::string& OutputVariable() const { return mOutputVariable; }

private:
    std::size_t Segment(double x) const;

    std::string mInputVariable;
    std::string mOutputVariable;
    std::vector<std::pair<double, double>> mRows;
};

}  // namespace contact_app
