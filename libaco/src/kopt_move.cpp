#include "kopt_move.h"

#include <stdexcept>
#include <vector>

namespace aco::detail::kopt {

namespace {

// Signed permutations of m segments as numbers: place p holds digit
// 2 (|x| - 1) + (x < 0) in base 2m.
int encode(int m, const int* x) {
  int code = 0;
  for (int p = m - 1; p >= 0; --p) code = code * 2 * m + 2 * ((x[p] < 0 ? -x[p] : x[p]) - 1) + (x[p] < 0 ? 1 : 0);
  return code;
}

void decode(int m, int code, int* x) {
  for (int p = 0; p < m; ++p) {
    const int digit = code % (2 * m);
    code /= 2 * m;
    x[p] = (digit / 2 + 1) * (digit % 2 == 1 ? -1 : 1);
  }
}

// For every signed permutation of m segments, the last reversal of a
// shortest way to it from the identity and the permutation before it
// (breadth first from the identity).
struct Table {
  std::vector<int> parent;                 // -1: not reached (not a permutation)
  std::vector<std::pair<int, int>> block;  // the reversal that led here
};

Table build(int m) {
  int size = 1;
  for (int p = 0; p < m; ++p) size *= 2 * m;
  Table table{std::vector<int>(static_cast<std::size_t>(size), -1), std::vector<std::pair<int, int>>(static_cast<std::size_t>(size))};
  int id[kMaxMoveK - 1];
  for (int p = 0; p < m; ++p) id[p] = p + 1;
  const int start = encode(m, id);
  table.parent[static_cast<std::size_t>(start)] = start;
  std::vector<int> queue{start};
  for (std::size_t head = 0; head < queue.size(); ++head) {
    int x[kMaxMoveK - 1];
    decode(m, queue[head], x);
    for (int i = 0; i < m; ++i) {
      for (int j = i; j < m; ++j) {
        int y[kMaxMoveK - 1];
        for (int p = 0; p < m; ++p) y[p] = x[p];
        for (int l = i, h = j; l <= h; ++l, --h) {
          const int a = x[l], b = x[h];
          y[l] = -b;
          y[h] = -a;
        }
        const int code = encode(m, y);
        if (table.parent[static_cast<std::size_t>(code)] >= 0) continue;
        table.parent[static_cast<std::size_t>(code)] = queue[head];
        table.block[static_cast<std::size_t>(code)] = {i, j};
        queue.push_back(code);
      }
    }
  }
  return table;
}

const Table& table_for(int m) {
  static const std::array<Table, kMaxMoveK> tables = [] {
    std::array<Table, kMaxMoveK> t;
    for (int size = 1; size < kMaxMoveK; ++size) t[static_cast<std::size_t>(size)] = build(size);
    return t;
  }();
  return tables[static_cast<std::size_t>(m)];
}

}  // namespace

int reversal_plan(int m, const int* target, std::array<std::pair<int, int>, 8>& blocks) {
  if (m < 1 || m >= kMaxMoveK) throw std::logic_error("reversal_plan: segments out of range");
  const Table& table = table_for(m);
  int id[kMaxMoveK - 1];
  for (int p = 0; p < m; ++p) id[p] = p + 1;
  const int start = encode(m, id);
  int code = encode(m, target);
  // Walked back from the target, the reversals come last first.
  int count = 0;
  std::pair<int, int> back[8];
  while (code != start) {
    if (count == 8 || table.parent[static_cast<std::size_t>(code)] < 0) throw std::logic_error("reversal_plan: not a signed permutation");
    back[count++] = table.block[static_cast<std::size_t>(code)];
    code = table.parent[static_cast<std::size_t>(code)];
  }
  for (int r = 0; r < count; ++r) blocks[static_cast<std::size_t>(r)] = back[count - 1 - r];
  return count;
}

}  // namespace aco::detail::kopt
