/*
 * Counts what each MPI rank of a run sends, by kind of call, through the
 * MPI profiling interface: build it as a shared library and preload it
 * into the ranks (benchmarks/weak_scaling.py does both):
 *
 *   mpicc -shared -fPIC -O2 benchmarks/mpi_bytes.c -o mpi_bytes.so
 *   mpirun -np 2 -x LD_PRELOAD=$PWD/mpi_bytes.so build/polyfrac ...
 *
 * At MPI_Finalize each rank appends one line to the file named by the
 * environment variable MPI_BYTES_FILE (stderr without it):
 *
 *   rank R p2p B N allreduce B N allgather B N bcast B N other B N
 *
 * B is the payload in bytes the rank hands to the calls of that kind (a
 * point-to-point send: its message; an all-reduce or a reduce: its
 * buffer; an all-gather: its contribution; a broadcast: the buffer, on the
 * root only; the rest: what the rank contributes), N the number of calls.
 * The payload is what the program asks to move: an all-reduce of B bytes
 * by a ring or recursive-doubling algorithm moves about 2 B per rank over
 * the network, an all-gather of B bytes per rank about (P - 1) B.
 * Open MPI's own monitoring component (pml_monitoring_enable) prints
 * nothing for polyfrac's runs (it does for a bare MPI program), hence this.
 *
 * With the environment variable MPI_BYTES_SITES set to a path, each rank R
 * also writes PATH.R: per call site, "B N kind | f | g" with f and g the
 * innermost two functions of libpolyfrac on the call's stack (mangled
 * names: pipe the file through c++filt), largest B first unsorted; what
 * moves the bytes, e.g. a whole-vector import after a Krylov solve.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <execinfo.h>
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum kind
{
  p2p,
  allreduce,
  allgather,
  bcast,
  other,
  n_kinds
};

static const char *kind_names[n_kinds] = {"p2p",
                                          "allreduce",
                                          "allgather",
                                          "bcast",
                                          "other"};
static double      bytes[n_kinds];
static long        calls[n_kinds];

/* The call sites of MPI_BYTES_SITES: their keys, bytes and calls. */
enum
{
  max_sites = 1024,
  key_length = 600
};
static char   site_keys[max_sites][key_length];
static double site_bytes[max_sites];
static long   site_calls[max_sites];
static int    n_sites = 0;

/* Adds @p b bytes of kind @p k to the call site of the caller's caller. */
static void
count_site(const enum kind k, const double b)
{
  void     *stack[48];
  const int depth = backtrace(stack, 48);
  char      key[key_length];
  int       length = snprintf(key, key_length, "%s", kind_names[k]);
  for (int i = 2, found = 0; i < depth && found < 2 && length < 500; ++i)
    {
      Dl_info info;
      if (dladdr(stack[i], &info) && info.dli_fname && info.dli_sname &&
          strstr(info.dli_fname, "libpolyfrac"))
        {
          length += snprintf(key + length,
                             key_length - length,
                             " | %.240s",
                             info.dli_sname);
          ++found;
        }
    }
  for (int s = 0; s < n_sites; ++s)
    if (strcmp(site_keys[s], key) == 0)
      {
        site_bytes[s] += b;
        ++site_calls[s];
        return;
      }
  if (n_sites < max_sites)
    {
      strcpy(site_keys[n_sites], key);
      site_bytes[n_sites] = b;
      site_calls[n_sites] = 1;
      ++n_sites;
    }
}

/* Adds @p count elements of @p type to the counters of @p k. */
static void
count(const enum kind k, const int n, const MPI_Datatype type)
{
  int size = 0;
  PMPI_Type_size(type, &size);
  bytes[k] += (double)n * size;
  ++calls[k];
  if (getenv("MPI_BYTES_SITES"))
    count_site(k, (double)n * size);
}

int
MPI_Send(const void *b, int n, MPI_Datatype t, int d, int g, MPI_Comm c)
{
  count(p2p, n, t);
  return PMPI_Send(b, n, t, d, g, c);
}

int
MPI_Isend(const void  *b,
          int          n,
          MPI_Datatype t,
          int          d,
          int          g,
          MPI_Comm     c,
          MPI_Request *r)
{
  count(p2p, n, t);
  return PMPI_Isend(b, n, t, d, g, c, r);
}

int
MPI_Rsend(const void *b, int n, MPI_Datatype t, int d, int g, MPI_Comm c)
{
  count(p2p, n, t);
  return PMPI_Rsend(b, n, t, d, g, c);
}

int
MPI_Ssend(const void *b, int n, MPI_Datatype t, int d, int g, MPI_Comm c)
{
  count(p2p, n, t);
  return PMPI_Ssend(b, n, t, d, g, c);
}

int
MPI_Sendrecv(const void  *sb,
             int          sn,
             MPI_Datatype st,
             int          d,
             int          sg,
             void        *rb,
             int          rn,
             MPI_Datatype rt,
             int          s,
             int          rg,
             MPI_Comm     c,
             MPI_Status  *status)
{
  count(p2p, sn, st);
  return PMPI_Sendrecv(sb, sn, st, d, sg, rb, rn, rt, s, rg, c, status);
}

int
MPI_Allreduce(const void  *sb,
              void        *rb,
              int          n,
              MPI_Datatype t,
              MPI_Op       o,
              MPI_Comm     c)
{
  count(allreduce, n, t);
  return PMPI_Allreduce(sb, rb, n, t, o, c);
}

int
MPI_Reduce(const void  *sb,
           void        *rb,
           int          n,
           MPI_Datatype t,
           MPI_Op       o,
           int          root,
           MPI_Comm     c)
{
  count(other, n, t);
  return PMPI_Reduce(sb, rb, n, t, o, root, c);
}

int
MPI_Allgather(const void  *sb,
              int          sn,
              MPI_Datatype st,
              void        *rb,
              int          rn,
              MPI_Datatype rt,
              MPI_Comm     c)
{
  count(allgather, sn, st);
  return PMPI_Allgather(sb, sn, st, rb, rn, rt, c);
}

int
MPI_Allgatherv(const void  *sb,
               int          sn,
               MPI_Datatype st,
               void        *rb,
               const int   *rn,
               const int   *displacements,
               MPI_Datatype rt,
               MPI_Comm     c)
{
  count(allgather, sn, st);
  return PMPI_Allgatherv(sb, sn, st, rb, rn, displacements, rt, c);
}

int
MPI_Bcast(void *b, int n, MPI_Datatype t, int root, MPI_Comm c)
{
  int rank = 0;
  PMPI_Comm_rank(c, &rank);
  if (rank == root)
    count(bcast, n, t);
  else
    ++calls[bcast];
  return PMPI_Bcast(b, n, t, root, c);
}

int
MPI_Gather(const void  *sb,
           int          sn,
           MPI_Datatype st,
           void        *rb,
           int          rn,
           MPI_Datatype rt,
           int          root,
           MPI_Comm     c)
{
  count(other, sn, st);
  return PMPI_Gather(sb, sn, st, rb, rn, rt, root, c);
}

int
MPI_Alltoall(const void  *sb,
             int          sn,
             MPI_Datatype st,
             void        *rb,
             int          rn,
             MPI_Datatype rt,
             MPI_Comm     c)
{
  int size = 1;
  PMPI_Comm_size(c, &size);
  count(other, sn * size, st);
  return PMPI_Alltoall(sb, sn, st, rb, rn, rt, c);
}

int
MPI_Alltoallv(const void  *sb,
              const int   *sn,
              const int   *sd,
              MPI_Datatype st,
              void        *rb,
              const int   *rn,
              const int   *rd,
              MPI_Datatype rt,
              MPI_Comm     c)
{
  int size = 1, total = 0;
  PMPI_Comm_size(c, &size);
  for (int r = 0; r < size; ++r)
    total += sn[r];
  count(other, total, st);
  return PMPI_Alltoallv(sb, sn, sd, st, rb, rn, rd, rt, c);
}

int
MPI_Gatherv(const void  *sb,
            int          sn,
            MPI_Datatype st,
            void        *rb,
            const int   *rn,
            const int   *displacements,
            MPI_Datatype rt,
            int          root,
            MPI_Comm     c)
{
  count(other, sn, st);
  return PMPI_Gatherv(sb, sn, st, rb, rn, displacements, rt, root, c);
}

int
MPI_Scan(const void *sb, void *rb, int n, MPI_Datatype t, MPI_Op o, MPI_Comm c)
{
  count(other, n, t);
  return PMPI_Scan(sb, rb, n, t, o, c);
}

int
MPI_Exscan(const void  *sb,
           void        *rb,
           int          n,
           MPI_Datatype t,
           MPI_Op       o,
           MPI_Comm     c)
{
  count(other, n, t);
  return PMPI_Exscan(sb, rb, n, t, o, c);
}

int
MPI_Finalize(void)
{
  int rank = 0;
  PMPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const char *name = getenv("MPI_BYTES_FILE");
  FILE       *file = name ? fopen(name, "a") : stderr;
  if (file)
    {
      fprintf(file, "rank %d", rank);
      for (int k = 0; k < n_kinds; ++k)
        fprintf(file, " %s %.0f %ld", kind_names[k], bytes[k], calls[k]);
      fprintf(file, "\n");
      if (file != stderr)
        fclose(file);
    }
  if (getenv("MPI_BYTES_SITES"))
    {
      char path[4096];
      snprintf(path, sizeof path, "%s.%d", getenv("MPI_BYTES_SITES"), rank);
      FILE *sites = fopen(path, "w");
      for (int s = 0; sites && s < n_sites; ++s)
        fprintf(sites,
                "%.0f %ld %s\n",
                site_bytes[s],
                site_calls[s],
                site_keys[s]);
      if (sites)
        fclose(sites);
    }
  return PMPI_Finalize();
}
