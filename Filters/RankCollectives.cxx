#include "RankCollectives.h"

#include "Fnv1a.h"
#include "PhaseLog.h"

#include "vtkAlgorithm.h"
#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace ptm
{
namespace
{
bool parallel(vtkMultiProcessController* c)
{
  return c != nullptr && c->GetNumberOfProcesses() > 1;
}

template <typename T>
std::vector<T> gather(vtkMultiProcessController* c, const std::vector<T>& local,
  std::vector<long long>* countsOut)
{
  phases::collective(c, "allgather", local.size() * sizeof(T));
  if (!parallel(c))
  {
    if (countsOut)
    {
      countsOut->assign(1, static_cast<long long>(local.size()));
    }
    return local;
  }
  const int n = c->GetNumberOfProcesses();
  vtkIdType mine = static_cast<vtkIdType>(local.size());
  std::vector<vtkIdType> counts(n), offsets(n);
  c->AllGather(&mine, counts.data(), 1);
  vtkIdType total = 0;
  for (int r = 0; r < n; ++r)
  {
    offsets[r] = total;
    total += counts[r];
  }
  std::vector<T> all(static_cast<std::size_t>(total));
  // AllGatherV wants a valid pointer even for zero-length pieces
  T dummy{};
  c->AllGatherV(local.empty() ? &dummy : local.data(), all.empty() ? &dummy : all.data(), mine,
    counts.data(), offsets.data());
  if (countsOut)
  {
    countsOut->assign(counts.begin(), counts.end());
  }
  return all;
}

// Collective: true on every rank when every rank passed the same `facts`
// (sizes and a hash of what it holds); true at once in serial.
bool sameOnEveryRank(vtkMultiProcessController* c, const std::vector<long long>& facts)
{
  if (!parallel(c))
  {
    return true;
  }
  const std::vector<long long> all = gather(c, facts, nullptr);
  for (std::size_t k = facts.size(); k < all.size(); ++k)
  {
    if (all[k] != all[k % facts.size()])
    {
      return false;
    }
  }
  return true;
}
// Element-wise reduction of a vector that has the same length on every rank.
template <typename T>
void allReduce(vtkMultiProcessController* c, std::vector<T>& values, int operation)
{
  phases::collective(c, "allreduce", values.size() * sizeof(T));
  if (!parallel(c) || values.empty())
  {
    return;
  }
  std::vector<T> result(values.size());
  c->AllReduce(values.data(), result.data(), static_cast<vtkIdType>(values.size()), operation);
  values.swap(result);
}
} // namespace

int rankOf(vtkMultiProcessController* c)
{
  return c ? c->GetLocalProcessId() : 0;
}

int rankCount(vtkMultiProcessController* c)
{
  return c ? std::max(1, c->GetNumberOfProcesses()) : 1;
}

bool agreeAllSucceeded(vtkMultiProcessController* c, bool localOk, const std::string& localError,
  std::string& message)
{
  message.clear();
  phases::collective(c, "agree", sizeof(int));
  if (!parallel(c))
  {
    message = localOk ? "" : localError;
    return localOk;
  }
  int ok = localOk ? 1 : 0, allOk = 0;
  c->AllReduce(&ok, &allOk, 1, vtkCommunicator::MIN_OP);
  if (allOk)
  {
    return true;
  }
  std::vector<char> text;
  if (!localOk)
  {
    const std::string line =
      "rank " + std::to_string(c->GetLocalProcessId()) + ": " + localError + "\n";
    text.assign(line.begin(), line.end());
  }
  const std::vector<char> all = gather(c, text, nullptr);
  message.assign(all.begin(), all.end());
  while (!message.empty() && message.back() == '\n')
  {
    message.pop_back();
  }
  // the same failure seen by every rank is reported once
  const std::size_t firstEnd = message.find('\n');
  if (firstEnd != std::string::npos)
  {
    const std::string first = message.substr(message.find(": ") + 2, firstEnd - message.find(": ") - 2);
    bool same = true;
    std::size_t start = 0;
    while (start < message.size())
    {
      std::size_t end = message.find('\n', start);
      if (end == std::string::npos)
      {
        end = message.size();
      }
      const std::string line = message.substr(start, end - start);
      const std::size_t colon = line.find(": ");
      same = same && colon != std::string::npos && line.substr(colon + 2) == first;
      start = end + 1;
    }
    if (same)
    {
      message = "all ranks: " + first;
    }
  }
  return false;
}

bool agreeAnyAborted(vtkMultiProcessController* c, vtkAlgorithm* algorithm)
{
  const bool localAbort = algorithm->CheckAbort();
  algorithm->SetAbortOutput(false);
  if (localAbort)
  {
    algorithm->SetAbortExecute(0); // honoured now; the next update runs normally
  }
  phases::collective(c, "abort", sizeof(int));
  if (!parallel(c))
  {
    return localAbort;
  }
  int mine = localAbort ? 1 : 0, any = 0;
  c->AllReduce(&mine, &any, 1, vtkCommunicator::MAX_OP);
  return any != 0;
}

TriangleSurface wholeSurfaceOnEveryRank(vtkMultiProcessController* c, const TriangleSurface& local)
{
  std::uint64_t hash = fnv1a(kFnv1aOffset, local.points.data(), local.points.size() * sizeof(Vec3));
  hash = fnv1a(hash, local.triangles.data(), local.triangles.size() * sizeof(Triangle));
  return sameOnEveryRank(c, { static_cast<long long>(local.points.size()),
                              static_cast<long long>(local.triangles.size()), static_cast<long long>(hash) })
    ? local
    : allGatherSurface(c, local);
}

std::vector<double> wholeValuesOnEveryRank(vtkMultiProcessController* c, const std::vector<double>& local)
{
  const std::uint64_t hash = fnv1a(kFnv1aOffset, local.data(), local.size() * sizeof(double));
  return sameOnEveryRank(c, { static_cast<long long>(local.size()), static_cast<long long>(hash) })
    ? local
    : gather(c, local, nullptr);
}

TriangleSurface allGatherSurface(vtkMultiProcessController* c, const TriangleSurface& local)
{
  if (!parallel(c))
  {
    return local;
  }
  std::vector<double> coordinates;
  coordinates.reserve(local.points.size() * 3);
  for (const auto& p : local.points)
  {
    coordinates.insert(coordinates.end(), p.begin(), p.end());
  }
  std::vector<long long> corners;
  corners.reserve(local.triangles.size() * 3);
  for (const auto& t : local.triangles)
  {
    corners.insert(corners.end(), t.begin(), t.end());
  }
  std::vector<long long> coordinateCounts;
  const std::vector<double> allCoordinates = gather(c, coordinates, &coordinateCounts);
  std::vector<long long> cornerCounts;
  const std::vector<long long> allCorners = gather(c, corners, &cornerCounts);

  TriangleSurface all;
  all.points.resize(allCoordinates.size() / 3);
  for (std::size_t i = 0; i < all.points.size(); ++i)
  {
    all.points[i] = { allCoordinates[3 * i], allCoordinates[3 * i + 1], allCoordinates[3 * i + 2] };
  }
  long long pointOffset = 0, cornerOffset = 0;
  for (std::size_t r = 0; r < cornerCounts.size(); ++r)
  {
    for (long long k = 0; k < cornerCounts[r]; k += 3)
    {
      const long long* t = &allCorners[cornerOffset + k];
      all.triangles.push_back({ t[0] + pointOffset, t[1] + pointOffset, t[2] + pointOffset });
    }
    cornerOffset += cornerCounts[r];
    pointOffset += coordinateCounts[r] / 3;
  }
  return all;
}

void allReduceMax(vtkMultiProcessController* c, std::vector<long long>& values)
{
  allReduce(c, values, vtkCommunicator::MAX_OP);
}

void allReduceMin(vtkMultiProcessController* c, std::vector<long long>& values)
{
  allReduce(c, values, vtkCommunicator::MIN_OP);
}

void allReduceSum(vtkMultiProcessController* c, std::vector<double>& values)
{
  allReduce(c, values, vtkCommunicator::SUM_OP);
}

std::vector<long long> allGatherValues(vtkMultiProcessController* c,
  const std::vector<long long>& local, std::vector<long long>* counts)
{
  return gather(c, local, counts);
}

std::vector<double> allGatherValues(vtkMultiProcessController* c, const std::vector<double>& local,
  std::vector<long long>* counts)
{
  return gather(c, local, counts);
}
} // namespace ptm
