// The products of hermite_kernels.h in GCC/Clang vector extensions. One
// source serves every instruction set: on x86-64 each entry point is
// compiled for x86-64-v3 (AVX2 and FMA) and for the baseline (SSE2), and the
// processor picks one at run time (GCC target_clones, or a test of the
// processor where the two versions use different vector widths). The
// x86-64-v3 versions use fused multiply-adds, so the last bits of a product
// (and possibly a Krylov or Newton iteration count) differ between
// processors with and without AVX2.
#include <nitsche_contact/solvers/hermite_kernels.h>

#include <cstdint>
#include <cstring>
#include <type_traits>

#if defined(__GNUC__) && defined(__x86_64__)
#define NITSCHE_CONTACT_X86_64_V3 1
#define NITSCHE_CONTACT_CLONES                                                 \
  __attribute__((target_clones("arch=x86-64-v3", "default")))
#define NITSCHE_CONTACT_V3 __attribute__((target("arch=x86-64-v3")))
#else
#define NITSCHE_CONTACT_X86_64_V3 0
#define NITSCHE_CONTACT_CLONES
#endif

#define NITSCHE_CONTACT_INLINE inline __attribute__((always_inline))

namespace NitscheContact
{
  namespace hermite_kernels
  {
    namespace
    {
      /// A vector of `bytes` bytes of Number, and the integer vector of
      /// the same shape (for shuffles).
      template <typename Number, unsigned int bytes> struct Simd
      {
        typedef Number type __attribute__((vector_size(bytes)));
        using Integer =
          std::conditional_t<sizeof(Number) == 4, std::int32_t, std::int64_t>;
        typedef Integer mask __attribute__((vector_size(bytes)));
      };

      template <typename V, typename Number>
      NITSCHE_CONTACT_INLINE V
      load(const Number *p)
      {
        V v;
        std::memcpy(&v, p, sizeof(V));
        return v;
      }

      template <typename V, typename Number>
      NITSCHE_CONTACT_INLINE void
      store(const V &v, Number *p)
      {
        std::memcpy(p, &v, sizeof(V));
      }

      /// Vertex (i, j) with whichever of its neighbours exist; V holds the
      /// four dofs of one vertex.
      template <typename Number, typename V>
      NITSCHE_CONTACT_INLINE void
      any_vertex(const Number      *x,
                 Number            *y,
                 const unsigned int nx,
                 const unsigned int ny,
                 const unsigned int i,
                 const unsigned int j,
                 const Number      *blocks)
      {
        const auto kind1 = [](unsigned int i, unsigned int n) {
          return i == 0 ? 0u : (i == n ? 2u : 1u);
        };
        const Number *b  = blocks + 144 * (kind1(i, nx) + 3 * kind1(j, ny));
        V             yv = {};
        for (int dy = (j > 0 ? -1 : 0); dy <= (j < ny ? 1 : 0); ++dy)
          for (int dx = (i > 0 ? -1 : 0); dx <= (i < nx ? 1 : 0); ++dx)
            {
              const Number *xw    = x + 4 * ((i + dx) + (nx + 1) * (j + dy));
              const Number *block = b + 16 * ((dx + 1) + 3 * (dy + 1));
              for (unsigned int kp = 0; kp < 4; ++kp)
                yv += load<V>(block + 4 * kp) * xw[kp];
            }
        store(yv, y + 4 * (i + (nx + 1) * j));
      }

      /// The interior vertices 1 <= i < nx of the interior vertex row j
      /// (the nine blocks of an interior vertex at b). A V holds the dofs of
      /// `per` adjacent vertices: with more than one, one load of x serves
      /// them all, and a shuffle spreads each of their four dofs over its
      /// vertex's lanes.
      template <typename Number, unsigned int bytes>
      NITSCHE_CONTACT_INLINE void
      interior_vertices(const Number      *x,
                        Number            *y,
                        const unsigned int nx,
                        const unsigned int j,
                        const Number      *b)
      {
        using V                      = typename Simd<Number, bytes>::type;
        using Mask                   = typename Simd<Number, bytes>::mask;
        constexpr unsigned int lanes = bytes / sizeof(Number);
        constexpr unsigned int per   = lanes / 4;
        static_assert(per >= 1 && lanes == 4 * per, "four dofs per vertex");
        const long row    = 4 * long(nx + 1);
        const long off[9] = {
          -row - 4, -row, -row + 4, -4, 0, 4, row - 4, row, row + 4};
        V    c[9][4];
        Mask spread[4];
        for (unsigned int l = 0; l < lanes; ++l)
          {
            for (unsigned int d = 0; d < 9; ++d)
              for (unsigned int kp = 0; kp < 4; ++kp)
                c[d][kp][l] = b[16 * d + 4 * kp + l % 4];
            for (unsigned int kp = 0; kp < 4; ++kp)
              spread[kp][l] = kp + 4 * (l / 4);
          }
        const long   first = row * j;
        unsigned int i     = 1;
        for (; i + per <= nx; i += per)
          {
            const Number *xv  = x + first + 4 * long(i);
            V             acc = {};
            for (unsigned int d = 0; d < 9; ++d)
              if constexpr (per == 1)
                for (unsigned int kp = 0; kp < 4; ++kp)
                  acc += c[d][kp] * xv[off[d] + kp];
              else
                {
                  const V xw = load<V>(xv + off[d]);
                  for (unsigned int kp = 0; kp < 4; ++kp)
                    acc += c[d][kp] * __builtin_shuffle(xw, spread[kp]);
                }
            store(acc, y + first + 4 * long(i));
          }
        for (; i < nx; ++i)
          {
            const Number *xv     = x + first + 4 * long(i);
            Number        acc[4] = {};
            for (unsigned int d = 0; d < 9; ++d)
              for (unsigned int kp = 0; kp < 4; ++kp)
                for (unsigned int k = 0; k < 4; ++k)
                  acc[k] += b[16 * d + 4 * kp + k] * xv[off[d] + kp];
            std::memcpy(y + first + 4 * long(i), acc, sizeof(acc));
          }
      }

      template <typename Number, unsigned int bytes>
      NITSCHE_CONTACT_INLINE void
      stencil(const Number      *x,
              Number            *y,
              const unsigned int nx,
              const unsigned int ny,
              const unsigned int j_begin,
              const unsigned int j_end,
              const Number      *blocks)
      {
        using V4 = typename Simd<Number, 4 * sizeof(Number)>::type;
        for (unsigned int j = j_begin; j < j_end; ++j)
          {
            any_vertex<Number, V4>(x, y, nx, ny, 0, j, blocks);
            if (j == 0 || j == ny)
              for (unsigned int i = 1; i < nx; ++i)
                any_vertex<Number, V4>(x, y, nx, ny, i, j, blocks);
            else
              interior_vertices<Number, bytes>(x, y, nx, j, blocks + 144 * 4);
            any_vertex<Number, V4>(x, y, nx, ny, nx, j, blocks);
          }
      }

      /// add_cell_products() with V holding the four dofs of one vertex
      /// (double) or of two (float): a cell's vertices 0, 1 (and 2, 3) are
      /// adjacent in x and y, so two vertices are one load or store.
      template <typename Number, unsigned int bytes>
      NITSCHE_CONTACT_INLINE void
      cell_products(const Number        *x,
                    Number              *y,
                    const unsigned int   nx,
                    const unsigned int   j,
                    const unsigned int  *cells,
                    const unsigned int   n_cells,
                    const Number *const *columns)
      {
        using V                    = typename Simd<Number, bytes>::type;
        constexpr unsigned int per = bytes / sizeof(Number) / 4;
        constexpr unsigned int n_v = 4 / per;
        const long             row = 4 * long(nx + 1);
        for (unsigned int e = 0; e < n_cells; ++e)
          {
            const long    v0 = 4 * (long(cells[e] % nx) + long(nx + 1) * j);
            const long    start[4] = {v0, v0 + 4, v0 + row, v0 + row + 4};
            const Number *cols     = columns[e];
            V             acc[n_v] = {};
            for (unsigned int w = 0; w < 4; ++w)
              for (unsigned int kp = 0; kp < 4; ++kp)
                {
                  const Number  xm  = x[start[w] + kp];
                  const Number *col = cols + 16 * (4 * w + kp);
                  for (unsigned int a = 0; a < n_v; ++a)
                    acc[a] += load<V>(col + 4 * per * a) * xm;
                }
            for (unsigned int a = 0; a < n_v; ++a)
              store(load<V>(y + start[per * a]) + acc[a], y + start[per * a]);
          }
      }

#if NITSCHE_CONTACT_X86_64_V3
      /// the float stencil with eight lanes (two vertices per vector)
      NITSCHE_CONTACT_V3 void
      stencil_rows_v3(const float       *x,
                      float             *y,
                      const unsigned int nx,
                      const unsigned int ny,
                      const unsigned int j_begin,
                      const unsigned int j_end,
                      const float       *blocks)
      {
        stencil<float, 32>(x, y, nx, ny, j_begin, j_end, blocks);
      }
#endif
    } // namespace



    void
    stencil_rows(const float       *x,
                 float             *y,
                 const unsigned int nx,
                 const unsigned int ny,
                 const unsigned int j_begin,
                 const unsigned int j_end,
                 const float       *blocks)
    {
      // Eight float lanes pay only with AVX2: without it the shuffles cost
      // more than the shared loads save.
#if NITSCHE_CONTACT_X86_64_V3
      static const bool v3 = __builtin_cpu_supports("x86-64-v3");
      if (v3)
        return stencil_rows_v3(x, y, nx, ny, j_begin, j_end, blocks);
#endif
      stencil<float, 16>(x, y, nx, ny, j_begin, j_end, blocks);
    }



    NITSCHE_CONTACT_CLONES void
    stencil_rows(const double      *x,
                 double            *y,
                 const unsigned int nx,
                 const unsigned int ny,
                 const unsigned int j_begin,
                 const unsigned int j_end,
                 const double      *blocks)
    {
      stencil<double, 32>(x, y, nx, ny, j_begin, j_end, blocks);
    }



    NITSCHE_CONTACT_CLONES void
    add_cell_products(const float        *x,
                      float              *y,
                      const unsigned int  nx,
                      const unsigned int  j,
                      const unsigned int *cells,
                      const unsigned int  n_cells,
                      const float *const *columns)
    {
      cell_products<float, 32>(x, y, nx, j, cells, n_cells, columns);
    }



    NITSCHE_CONTACT_CLONES void
    add_cell_products(const double        *x,
                      double              *y,
                      const unsigned int   nx,
                      const unsigned int   j,
                      const unsigned int  *cells,
                      const unsigned int   n_cells,
                      const double *const *columns)
    {
      cell_products<double, 32>(x, y, nx, j, cells, n_cells, columns);
    }
  } // namespace hermite_kernels
} // namespace NitscheContact
