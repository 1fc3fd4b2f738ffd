// BenchCosineNoise: what the closed form of vtkCosineNoise buys, and how
// fast vtkCosineNoiseSource fills a volume.
//
// 1. Optical depth along rays. For 1..8 octaves of the default noise (24
//    directions, frequency 1, lacunarity 2, gain 0.5, random phases) with the
//    offset set to minus the noise's lower bound (so the noise is
//    non-negative and the closed form is exact), a fixed, seeded set of rays
//    (origins in [-1, 1]^3, random unit directions, length 2) is integrated
//    a) by the closed form, ComputeOpticalDepth(o, w, 0, L), and
//    b) by ray marching: the midpoint rule with N equal steps, one
//       EvaluateFunction() per step.
//    N is the smallest step count (found by doubling, then bisection; the
//    error is not strictly monotone in N, so "smallest" is that of the
//    search) whose maximum relative error over the ray set, against the
//    closed form as the exact reference, is at most 1e-4. The reference is
//    cross-checked against adaptive Gauss-Kronrod quadrature on a subset of
//    the rays. Both are timed single-threaded with std::chrono::steady_clock:
//    trials of repeated passes over the ray set, alternating between the
//    two so that both see the same machine load, the best trial of each
//    counting; results go into a volatile sink so that the work cannot be
//    optimised away.
// 2. vtkCosineNoiseSource throughput at 256^3 over [-1, 1]^3 (its default
//    noise), with the default ellipsoid envelope and with no envelope, with
//    all vtkSMPTools threads and with one (vtkSMPTools::LocalScope); best of
//    a few Modified(); Update() runs.
//
// Usage: BenchCosineNoise [--quick] [--threads N] [--help]
#include "vtkCosineNoise.h"
#include "vtkCosineNoiseSource.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkSMPTools.h"
#include "vtkVersion.h"

#include "TyndallTestQuadrature.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace
{
volatile double Sink = 0.0;

using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point a, Clock::time_point b)
{
  return std::chrono::duration<double>(b - a).count();
}

struct Ray
{
  double O[3];
  double W[3];
};

struct Options
{
  bool Quick = false;
  int Threads = 0; // 0: the vtkSMPTools default
};

// One timing trial: calls pass() (one pass over the work, returning a
// checksum) repeatedly until at least minSeconds have elapsed; returns passes
// per second.
template <typename Pass>
double PassesPerSecond(Pass&& pass, double minSeconds)
{
  long passes = 0;
  double sum = 0.0;
  const Clock::time_point start = Clock::now();
  double elapsed = 0.0;
  do
  {
    sum += pass();
    ++passes;
    elapsed = Seconds(start, Clock::now());
  } while (elapsed < minSeconds);
  Sink = Sink + sum;
  return passes / elapsed;
}

// Ray marching: the midpoint rule with n steps over [0, length], one noise
// evaluation per step, scaled by the extinction scale. The same arithmetic as
// tyndall_test::MidpointRule, without the std::function indirection, so that
// the ray marcher is timed at its best.
double RayMarch(vtkCosineNoise* noise, const Ray& ray, double length, int n)
{
  const double h = length / n;
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
  {
    const double t = (i + 0.5) * h;
    double x[3] = { ray.O[0] + t * ray.W[0], ray.O[1] + t * ray.W[1], ray.O[2] + t * ray.W[2] };
    sum += noise->EvaluateFunction(x);
  }
  return noise->GetExtinctionScale() * sum * h;
}

// Maximum relative error of the n-step ray marcher over the rays. The ray
// that was worst in the previous call is tried first, so that a failing n is
// usually rejected after one ray (early exit once above the limit).
double MaxRelativeError(vtkCosineNoise* noise, const std::vector<Ray>& rays,
  const std::vector<double>& reference, double length, int n, double limit, size_t& worstRay)
{
  double worst = 0.0;
  const size_t count = rays.size();
  const size_t first = worstRay;
  for (size_t r = 0; r < count; ++r)
  {
    const size_t i = (r == 0) ? first : (r <= first ? r - 1 : r);
    const double error =
      std::abs(RayMarch(noise, rays[i], length, n) - reference[i]) / std::abs(reference[i]);
    if (error > worst)
    {
      worst = error;
      worstRay = i;
    }
    if (worst > limit)
    {
      break;
    }
  }
  return worst;
}

// Smallest n (doubling, then bisection) with a maximum relative error <= limit.
int StepsForAccuracy(vtkCosineNoise* noise, const std::vector<Ray>& rays,
  const std::vector<double>& reference, double length, double limit, double& achieved)
{
  size_t worstRay = 0;
  int hi = 1;
  double errorHi = MaxRelativeError(noise, rays, reference, length, hi, limit, worstRay);
  while (errorHi > limit)
  {
    if (hi >= (1 << 24))
    {
      achieved = errorHi;
      return -1;
    }
    hi *= 2;
    errorHi = MaxRelativeError(noise, rays, reference, length, hi, limit, worstRay);
  }
  int lo = hi / 2; // fails (or 0)
  while (hi - lo > 1)
  {
    const int mid = lo + (hi - lo) / 2;
    const double error = MaxRelativeError(noise, rays, reference, length, mid, limit, worstRay);
    if (error <= limit)
    {
      hi = mid;
      errorHi = error;
    }
    else
    {
      lo = mid;
    }
  }
  achieved = errorHi;
  return hi;
}

void PrintHelp(const char* program)
{
  std::printf("Usage: %s [--quick] [--threads N] [--help]\n"
              "  Benchmarks vtkCosineNoise's closed-form optical depth against ray marching\n"
              "  at equal accuracy (1e-4 relative), and vtkCosineNoiseSource throughput.\n"
              "  --quick      fewer rays, shorter timings and a 64^3 volume (smoke run)\n"
              "  --threads N  vtkSMPTools::Initialize(N) before anything runs\n"
              "  --help       this text\n",
    program);
}

//------------------------------------------------------------------------------
bool RayBenchmark(const Options& options)
{
  const int nRays = options.Quick ? 50 : 200;
  const double length = 2.0;
  const double limit = 1.0e-4;
  const double minSeconds = options.Quick ? 0.02 : 0.06;
  const int trials = options.Quick ? 2 : 5;
  const int crossCheckRays = options.Quick ? 5 : 20;

  std::mt19937 rng(20240607u);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<Ray> rays(nRays);
  for (Ray& ray : rays)
  {
    for (int c = 0; c < 3; ++c)
    {
      ray.O[c] = uniform(rng);
    }
    do
    {
      for (int c = 0; c < 3; ++c)
      {
        ray.W[c] = normal(rng);
      }
    } while (vtkMath::Normalize(ray.W) < 1.0e-6);
  }

  std::printf("1. Optical depth along rays: closed form vs. ray marching at equal accuracy\n");
  std::printf("   noise: 24 directions, frequency 1, lacunarity 2, gain 0.5, amplitude 1,\n"
              "          random phases, offset = -GetMinimumValue() at offset 0 (noise >= 0),\n"
              "          extinction scale 1\n");
  std::printf("   rays: %d, seeded; origins uniform in [-1,1]^3, random unit directions,"
              " t in [0, %g]\n",
    nRays, length);
  std::printf("   ray marching: midpoint rule, N steps, one EvaluateFunction() per step;\n"
              "   N = smallest step count (doubling, then bisection) with max relative error\n"
              "   over the rays <= %g against the closed form as the exact reference\n",
    limit);
  std::printf("   timing: single thread, steady_clock, best of %d alternating\n"
              "   trials of >= %g s each (closed form and ray marcher alternate)\n\n",
    trials, minSeconds);

  std::printf("   %7s | %5s | %9s | %9s | %13s | %13s | %8s | %9s\n", "octaves", "waves",
    "samples N", "max error", "closed eval/s", "marched eval/s", "speed-up", "GK check");
  std::printf("   --------+-------+-----------+-----------+---------------+----------------+"
              "----------+----------\n");

  double speedUpAt6 = -1.0;
  bool ok = true;
  for (int octaves = 1; octaves <= 8; ++octaves)
  {
    vtkNew<vtkCosineNoise> noise;
    noise->SetNumberOfOctaves(octaves);
    noise->SetFrequency(1.0);
    noise->SetOffset(0.0);
    noise->SetOffset(-noise->GetMinimumValue());
    const int waves = noise->GetNumberOfWaves();

    // The reference: the closed form, exact for non-negative noise.
    std::vector<double> reference(nRays);
    for (int r = 0; r < nRays; ++r)
    {
      reference[r] = noise->ComputeOpticalDepth(rays[r].O, rays[r].W, 0.0, length);
    }

    // Cross-check of the reference against adaptive Gauss-Kronrod (1e-12).
    double gkError = 0.0;
    for (int r = 0; r < crossCheckRays && r < nRays; ++r)
    {
      const Ray& ray = rays[r];
      auto f = [&](double t)
      {
        double x[3] = { ray.O[0] + t * ray.W[0], ray.O[1] + t * ray.W[1], ray.O[2] + t * ray.W[2] };
        return noise->EvaluateFunction(x);
      };
      const double gk =
        tyndall_test::AdaptiveIntegrate(f, 0.0, length, 1.0e-12 * std::abs(reference[r]));
      gkError = std::max(gkError, std::abs(gk - reference[r]) / std::abs(reference[r]));
    }

    double achieved = 0.0;
    const int n = StepsForAccuracy(noise, rays, reference, length, limit, achieved);
    if (n < 0)
    {
      std::printf("   %7d | %5d | no N up to 2^24 reaches the accuracy\n", octaves, waves);
      ok = false;
      continue;
    }

    auto closedPass = [&]()
    {
      double sum = 0.0;
      for (const Ray& ray : rays)
      {
        sum += noise->ComputeOpticalDepth(ray.O, ray.W, 0.0, length);
      }
      return sum;
    };
    auto marchedPass = [&]()
    {
      double sum = 0.0;
      for (const Ray& ray : rays)
      {
        sum += RayMarch(noise, ray, length, n);
      }
      return sum;
    };
    // Trials alternate between the two, so that both see the same machine
    // load; the best trial of each counts.
    double closedRate = 0.0;
    double marchedRate = 0.0;
    for (int trial = 0; trial < trials; ++trial)
    {
      closedRate = std::max(closedRate, nRays * PassesPerSecond(closedPass, minSeconds));
      marchedRate = std::max(marchedRate, nRays * PassesPerSecond(marchedPass, minSeconds));
    }
    const double speedUp = closedRate / marchedRate;
    if (octaves == 6)
    {
      speedUpAt6 = speedUp;
    }
    std::printf("   %7d | %5d | %9d | %9.3e | %13.6g | %14.6g | %7.4gx | %9.2e\n", octaves, waves,
      n, achieved, closedRate, marchedRate, speedUp, gkError);
    std::fflush(stdout);
  }
  std::printf("\n   max error: max relative error of the ray marcher with N steps (<= %g);\n"
              "   GK check: max relative difference between the closed form and adaptive\n"
              "   Gauss-Kronrod quadrature (tolerance 1e-12 relative) on the first %d rays.\n",
    limit, std::min(crossCheckRays, nRays));
  if (speedUpAt6 > 0.0)
  {
    std::printf("\nbar: speed-up >= 20x at 6 octaves (paper: 17x over delta tracking): %s "
                "(measured %.4gx)\n\n",
      speedUpAt6 >= 20.0 ? "PASS" : "MISS", speedUpAt6);
  }
  else
  {
    std::printf("\nbar: speed-up >= 20x at 6 octaves (paper: 17x over delta tracking): MISS "
                "(not measured)\n\n");
  }
  return ok;
}

//------------------------------------------------------------------------------
struct SourceResult
{
  double VoxelsPerSecond = 0.0; // best run
  double CpuPerWall = 0.0;      // process CPU time / wall time of that run
  int Threads = 0;              // vtkSMPTools::GetEstimatedNumberOfThreads()
};

// Best voxels per second of a few Modified(); Update() runs.
SourceResult SourceRate(vtkCosineNoiseSource* source, int runs)
{
  SourceResult result;
  result.Threads = vtkSMPTools::GetEstimatedNumberOfThreads();
  for (int run = 0; run < runs; ++run)
  {
    source->Modified();
    const std::clock_t cpuStart = std::clock();
    const Clock::time_point start = Clock::now();
    source->Update();
    const double elapsed = Seconds(start, Clock::now());
    const double cpu = static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    vtkImageData* image = source->GetOutput();
    const double voxels = static_cast<double>(image->GetNumberOfPoints());
    double range[2] = { 0.0, 0.0 };
    if (voxels > 0.0)
    {
      image->GetScalarRange(range);
    }
    Sink = Sink + range[1];
    if (voxels > 0.0 && elapsed > 0.0 && voxels / elapsed > result.VoxelsPerSecond)
    {
      result.VoxelsPerSecond = voxels / elapsed;
      result.CpuPerWall = cpu / elapsed;
    }
  }
  return result;
}

bool SourceBenchmark(const Options& options)
{
  const int size = options.Quick ? 64 : 256;
  const int runs = 2;

  {
    vtkNew<vtkCosineNoiseSource> defaults;
    std::printf("2. vtkCosineNoiseSource throughput (its default noise: %d octaves, %d waves)\n",
      defaults->GetNoise()->GetNumberOfOctaves(), defaults->GetNoise()->GetNumberOfWaves());
  }
  std::printf("   volume: %d^3 over [-1, 1]^3 (spacing 2/%d), best of %d Modified(); Update()\n",
    size, size - 1, runs);
  std::printf("   hardware threads (std::thread::hardware_concurrency): %u\n",
    std::thread::hardware_concurrency());
  std::printf("   vtkSMPTools backend: %s; estimated threads: %d%s\n", vtkSMPTools::GetBackend(),
    vtkSMPTools::GetEstimatedNumberOfThreads(),
    options.Threads > 0 ? " (set with --threads)" : " (default)");
  std::printf("   one thread: vtkSMPTools::LocalScope(Config{ 1 }, ...), after the default runs\n");
  std::printf("   cpu/wall: process CPU time / wall time of the best run (the threads that\n"
              "   actually worked; the machine may be shared)\n\n");

  const int envelopes[2] = { vtkCosineNoiseSource::ENVELOPE_ELLIPSOID,
    vtkCosineNoiseSource::ENVELOPE_NONE };
  const char* names[2] = { "ellipsoid", "none" };
  vtkNew<vtkCosineNoiseSource> sources[2];
  for (int e = 0; e < 2; ++e)
  {
    sources[e]->SetWholeExtent(0, size - 1, 0, size - 1, 0, size - 1);
    sources[e]->SetOrigin(-1.0, -1.0, -1.0);
    const double h = 2.0 / (size - 1);
    sources[e]->SetSpacing(h, h, h);
    sources[e]->SetEnvelopeType(envelopes[e]);
  }

  SourceResult all[2], one[2];
  for (int e = 0; e < 2; ++e)
  {
    all[e] = SourceRate(sources[e], runs);
  }
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ 1 },
    [&]()
    {
      for (int e = 0; e < 2; ++e)
      {
        one[e] = SourceRate(sources[e], runs);
      }
    });

  std::printf(
    "   %-10s | %7s | %16s | %8s | %8s\n", "envelope", "threads", "voxels/s", "Mvox/s", "cpu/wall");
  std::printf("   -----------+---------+------------------+----------+---------\n");
  bool ok = true;
  for (int e = 0; e < 2; ++e)
  {
    for (const SourceResult* r : { &all[e], &one[e] })
    {
      std::printf("   %-10s | %7d | %16.6g | %8.4g | %8.3g\n", names[e], r->Threads,
        r->VoxelsPerSecond, r->VoxelsPerSecond * 1e-6, r->CpuPerWall);
      ok = ok && r->VoxelsPerSecond > 0.0;
    }
    std::printf("   %-10s   parallel speed-up: %.3gx\n", "",
      one[e].VoxelsPerSecond > 0.0 ? all[e].VoxelsPerSecond / one[e].VoxelsPerSecond : 0.0);
  }
  std::printf("\n");
  return ok;
}
}

//------------------------------------------------------------------------------
int main(int argc, char* argv[])
{
  Options options;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h")
    {
      PrintHelp(argv[0]);
      return EXIT_SUCCESS;
    }
    else if (arg == "--quick")
    {
      options.Quick = true;
    }
    else if (arg == "--threads" && i + 1 < argc)
    {
      char* end = nullptr;
      const long n = std::strtol(argv[++i], &end, 10);
      if (!end || *end != '\0' || n < 1 || n > 4096)
      {
        std::fprintf(stderr, "--threads needs a positive integer, got '%s'\n", argv[i]);
        return EXIT_FAILURE;
      }
      options.Threads = static_cast<int>(n);
    }
    else
    {
      std::fprintf(stderr, "unknown argument '%s'\n", argv[i]);
      PrintHelp(argv[0]);
      return EXIT_FAILURE;
    }
  }
  if (options.Threads > 0)
  {
    vtkSMPTools::Initialize(options.Threads);
  }

  std::printf("BenchCosineNoise (VTK %s)%s\n\n", vtkVersion::GetVTKVersion(),
    options.Quick ? ", --quick: smoke-run sizes, numbers not representative" : "");
  // Other processes compete for the cores; the load average says how much.
  std::ifstream loadavg("/proc/loadavg");
  std::string load;
  if (loadavg && std::getline(loadavg, load))
  {
    std::printf("load average at start (/proc/loadavg): %s\n\n", load.c_str());
  }
  const Clock::time_point start = Clock::now();
  bool ok = RayBenchmark(options);
  ok = SourceBenchmark(options) && ok;
  std::printf("total time: %.1f s\n", Seconds(start, Clock::now()));
  std::printf("checksum (ignore): %g\n", static_cast<double>(Sink));
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
