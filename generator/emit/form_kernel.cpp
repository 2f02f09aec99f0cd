// Emits the form kernel: runtime/local_matrix.hpp's formula for the dense local matrix,
//   M[i+1][k+1] = -c_i T_ik        M[i+1][0] =  c_i sum_k T_ik
//   M[0][k+1]   = sum_i c_i T_ik   M[0][0]   = -sum_i c_i sum_k T_ik,
//   T_ik = delta_ik direct_i + sum_s left_i[s] (x) right_k[s],  c_i = V0 V_i,
// with the dimension and state count fixed and every product with a structurally zero
// factor entry left out (not multiplied by zero at run time). For correspondence in 2D
// each neighbour-block entry then costs 2 multiply-adds instead of 4 (3 instead of 9 in
// 3D): dN_ij/dY_k has one nonzero component. The state sums keep ascending s, as in the
// generic forming, so both give the same values.
#include "pdgen/form_kernel.hpp"

#include <sstream>

#include "emit/abi_text.hpp"

namespace pdgen {

namespace {
std::string str(int i) { return std::to_string(i); }

// "a + b + c", or "0.0" for no terms.
std::string sum_of(const std::vector<std::string>& terms) {
  if (terms.empty()) return "0.0";
  std::string s = terms[0];
  for (std::size_t i = 1; i < terms.size(); ++i) s += " + " + terms[i];
  return s;
}

class FormWriter {
 public:
  explicit FormWriter(const FactorStructure& fs) : fs_(fs), D_(fs.dim), S_(fs.n_states) {}

  bool left(int s, int r) const { return fs_.left[static_cast<std::size_t>(s * D_ + r)]; }
  bool right(int s, int q) const { return fs_.right[static_cast<std::size_t>(s * D_ + q)]; }
  bool direct(int r, int q) const { return fs_.direct[static_cast<std::size_t>(r * D_ + q)]; }
  std::string fac(const std::string& which, const std::string& bond, int per_bond, int index) const {
    return abi_text::factor_at(which, bond, per_bond, index);
  }
  std::string rs(int s, int q) const { return "rs_" + str(s) + "_" + str(q); }
  std::string ls(int s, int r) const { return "ls_" + str(s) + "_" + str(r); }
  std::string center(int r, int q) const { return "center_" + str(r) + "_" + str(q); }

  std::string body(int& neighbour_terms) const {
    std::ostringstream o;
    const std::string n = "n";
    o << "  const int L = " << abi_text::bond_count() << ";\n";
    o << "  const std::ptrdiff_t " << n << " = static_cast<std::ptrdiff_t>(L + 1) * " << D_ << ";\n";
    o << "  const double V0 = " << abi_text::center_volume() << ";\n";
    // Sums over the bonds of right_k and of c_k left_k, for the center row and column.
    bool any_sum = false;
    for (int s = 0; s < S_; ++s)
      for (int a = 0; a < D_; ++a) {
        if (right(s, a)) o << "  double " << rs(s, a) << " = 0.0;\n", any_sum = true;
        if (left(s, a)) o << "  double " << ls(s, a) << " = 0.0;\n", any_sum = true;
      }
    if (any_sum) {
      // In bond order, no simd reduction: O(L) work, and the same sums as the generic forming.
      o << "  for (int k = 0; k < L; ++k) {\n    const double c = V0 * " << abi_text::bond_volume("k")
        << ";\n";
      for (int s = 0; s < S_; ++s)
        for (int a = 0; a < D_; ++a) {
          if (right(s, a))
            o << "    " << rs(s, a) << " += " << fac("right", "k", S_ * D_, s * D_ + a) << ";\n";
          if (left(s, a))
            o << "    " << ls(s, a) << " += c * " << fac("left", "k", S_ * D_, s * D_ + a) << ";\n";
        }
      o << "  }\n";
    }
    for (int r = 0; r < D_; ++r)
      for (int q = 0; q < D_; ++q) o << "  double " << center(r, q) << " = 0.0;\n";
    // Neighbour rows.
    o << "  for (int i = 0; i < L; ++i) {\n    const double c = V0 * " << abi_text::bond_volume("i") << ";\n";
    neighbour_terms = 0;
    for (int r = 0; r < D_; ++r) {
      o << "    {\n      double* __restrict row = M + (static_cast<std::ptrdiff_t>(i + 1) * " << D_ << " + "
        << r << ") * n;\n";
      std::vector<std::vector<std::string>> entry(static_cast<std::size_t>(D_));
      for (int s = 0; s < S_; ++s) {
        if (!left(s, r)) continue;
        bool used = false;
        for (int q = 0; q < D_; ++q)
          if (right(s, q)) {
            entry[static_cast<std::size_t>(q)].push_back("a_" + str(s) + " * " +
                                                         fac("right", "k", S_ * D_, s * D_ + q));
            used = true;
          }
        if (used)
          o << "      const double a_" << s << " = -c * " << fac("left", "i", S_ * D_, s * D_ + r) << ";\n";
      }
      o << "#pragma omp simd\n      for (int k = 0; k < L; ++k) {\n";
      for (int q = 0; q < D_; ++q) {
        o << "        row[" << D_ << " + k * " << D_ << " + " << q
          << "] = " << sum_of(entry[static_cast<std::size_t>(q)]) << ";\n";
        neighbour_terms += static_cast<int>(entry[static_cast<std::size_t>(q)].size());
      }
      o << "      }\n";
      for (int q = 0; q < D_; ++q) {
        // Diagonal block: the direct term; center column: c_i (direct_i + sum_s left_i[s] (x) sum_k
        // right_k[s]).
        std::vector<std::string> v;
        if (direct(r, q)) {
          const std::string dv = fac("direct", "i", D_ * D_, r * D_ + q);
          o << "      row[(i + 1) * " << D_ << " + " << q << "] -= c * " << dv << ";\n";
          v.push_back(dv);
        }
        for (int s = 0; s < S_; ++s)
          if (left(s, r) && right(s, q))
            v.push_back(fac("left", "i", S_ * D_, s * D_ + r) + " * " + rs(s, q));
        o << "      {\n        const double v = c * (" << sum_of(v) << ");\n        row[" << q
          << "] = v;\n        " << center(r, q) << " -= v;\n      }\n";
      }
      o << "    }\n";
    }
    o << "  }\n";
    // Center rows: c_k direct_k + sum_s (sum_i c_i left_i[s]) (x) right_k[s].
    for (int r = 0; r < D_; ++r) {
      o << "  {\n    double* __restrict row = M + " << r << " * n;\n";
      for (int q = 0; q < D_; ++q) o << "    row[" << q << "] = " << center(r, q) << ";\n";
      o << "#pragma omp simd\n    for (int k = 0; k < L; ++k) {\n";
      bool need_c = false;
      for (int q = 0; q < D_; ++q) need_c = need_c || direct(r, q);
      if (need_c) o << "      const double c = V0 * " << abi_text::bond_volume("k") << ";\n";
      for (int q = 0; q < D_; ++q) {
        std::vector<std::string> v;
        if (direct(r, q)) v.push_back("c * " + fac("direct", "k", D_ * D_, r * D_ + q));
        for (int s = 0; s < S_; ++s)
          if (left(s, r) && right(s, q))
            v.push_back(ls(s, r) + " * " + fac("right", "k", S_ * D_, s * D_ + q));
        o << "      row[(k + 1) * " << D_ << " + " << q << "] = " << sum_of(v) << ";\n";
      }
      o << "    }\n  }\n";
    }
    return o.str();
  }

 private:
  const FactorStructure& fs_;
  int D_, S_;
};
}  // namespace

EmittedKernel emit_form_kernel(const std::string& name, const FactorStructure& structure) {
  const abi_text::Signature sig = abi_text::signature(abi_text::Kernel::Form);
  std::string params;
  for (std::size_t i = 0; i < sig.params.size(); ++i) params += (i ? ", " : "") + sig.params[i];
  const std::string proto = sig.return_type + " " + name + "(" + params + ")";
  int terms = 0;
  const std::string body = FormWriter(structure).body(terms);
  int zeros = 0;
  for (bool b : structure.right) zeros += !b;
  for (bool b : structure.left) zeros += !b;
  for (bool b : structure.direct) zeros += !b;
  EmittedKernel k;
  k.declaration = proto + ";";
  k.per_bond = {terms, terms, 0, 0};
  const int dense_terms = structure.dim * structure.dim * structure.n_states;
  k.code = "// " + name +
           ": the dense local matrix from the factors; per neighbour-block entry pair (i, k) " + str(terms) +
           " multiply-adds per d x d block (" + str(dense_terms) + " without the structure); " + str(zeros) +
           " structurally zero factor entries skipped\n" + proto + " {\n" + body + "}\n";
  return k;
}

}  // namespace pdgen
