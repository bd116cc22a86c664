// Slope bounds of the bilinear surface, for the grid and per quadtree block (private).

#include "terrain/slope_levels.hpp"

#include <algorithm>
#include <cmath>

namespace marsokhod::world {
namespace {

// Single precision keeps the loops vectorised; the bounds are then widened by far more than
// their rounding error.
constexpr double kRoundingAllowance = 1.0 + 1e-5;

int blocks(int cells, int level) {
  return (cells + (1 << level) - 1) >> level;
}

} // namespace

// On a bilinear cell dh/dx varies linearly across the cell, so its extremes lie on the two
// edges along x, and likewise for y; the gradient is at most the root of the sum of the two
// squared extremes. Over any union of cells the largest cell bound is a Lipschitz constant for
// segments inside that union, since a straight ground segment is a chain of pieces inside cells.
SlopeLevels slope_levels(const HeightField& height, int first_level) {
  SlopeLevels result;
  const int cells_x = height.nx() - 1;
  const int cells_y = height.ny() - 1;
  if (cells_x < 1 || cells_y < 1)
    return result;
  const int side = 1 << first_level;
  const int width = blocks(cells_x, first_level);
  const int rows = blocks(cells_y, first_level);
  std::vector<float> squared(static_cast<std::size_t>(width) * rows, 0.0F);
  std::vector<float> cell(static_cast<std::size_t>(cells_x));
  std::vector<float> row_blocks(static_cast<std::size_t>(width));
  const imaging::Image<float>& nodes = height.nodes();
  float steepest_squared = 0.0F;
  for (int j = 0; j < cells_y; ++j) {
    const float* near = nodes.row(j);
    const float* far = nodes.row(j + 1);
    for (int i = 0; i < cells_x; ++i) {
      const float along_x =
          std::max(std::abs(near[i + 1] - near[i]), std::abs(far[i + 1] - far[i]));
      const float along_y =
          std::max(std::abs(far[i] - near[i]), std::abs(far[i + 1] - near[i + 1]));
      cell[i] = along_x * along_x + along_y * along_y;
      steepest_squared = std::max(steepest_squared, cell[i]);
    }
    // Cells bx * side - 1 .. (bx + 1) * side of this row belong to block bx widened by a cell.
    for (int bx = 0; bx < width; ++bx) {
      const int from = std::max(0, bx * side - 1);
      const int to = std::min(cells_x, (bx + 1) * side + 1);
      row_blocks[bx] = *std::max_element(cell.begin() + from, cell.begin() + to);
    }
    // This row belongs to the widened blocks that hold the rows j - 1, j and j + 1.
    const int by_last = std::min(j + 1, cells_y - 1) >> first_level;
    for (int by = std::max(j - 1, 0) >> first_level; by <= by_last; ++by) {
      float* block = squared.data() + static_cast<std::size_t>(by) * width;
      for (int bx = 0; bx < width; ++bx)
        block[bx] = std::max(block[bx], row_blocks[bx]);
    }
  }
  const double per_cell = kRoundingAllowance / height.cell_m();
  result.steepest = std::sqrt(static_cast<double>(steepest_squared)) * per_cell;
  for (float& value : squared)
    value = static_cast<float>(std::sqrt(static_cast<double>(value)) * per_cell);
  result.levels.push_back(std::move(squared));
  for (int below_width = width, below_rows = rows; below_width > 1 || below_rows > 1;) {
    const int above_width = (below_width + 1) / 2;
    const int above_rows = (below_rows + 1) / 2;
    std::vector<float> above(static_cast<std::size_t>(above_width) * above_rows, 0.0F);
    const std::vector<float>& below = result.levels.back();
    for (int j = 0; j < below_rows; ++j)
      for (int i = 0; i < below_width; ++i) {
        float& parent = above[static_cast<std::size_t>(j / 2) * above_width + i / 2];
        parent = std::max(parent, below[static_cast<std::size_t>(j) * below_width + i]);
      }
    result.levels.push_back(std::move(above));
    below_width = above_width;
    below_rows = above_rows;
  }
  return result;
}

} // namespace marsokhod::world
