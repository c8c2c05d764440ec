#include "RankCollectives.h"

#include "Fnv1a.h"
#include "PhaseLog.h"

#include "vtkAlgorithm.h"
#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <unordered_map>

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

/// @name Exchanges between pairs of ranks
/// @{
constexpr int kExchangeTag = 7240;

// The rank `rank` meets in round `round` of a round-robin tournament (the
// circle method: every pair of ranks meets exactly once in n - 1 rounds, n
// the rank count rounded up to even); -1 where it sits the round out.
int partnerInRound(int rank, int ranks, int round)
{
  const int n = ranks + ranks % 2;
  int partner = 0;
  if (rank == n - 1)
  {
    partner = round;
  }
  else if (rank == round)
  {
    partner = n - 1;
  }
  else
  {
    partner = ((2 * round - rank) % (n - 1) + (n - 1)) % (n - 1);
  }
  return partner < ranks ? partner : -1;
}

// Sends outgoing[r] to every rank r; returns by rank what each sent here,
// incomingCounts[r] values from rank r (both ends know every length, so
// empty messages are not sent at all). Ranks meet in pairs, round by round,
// the lower rank sending first: blocking sends never wait on each other in
// a cycle.
std::vector<std::vector<long long>> exchangeWithRanks(vtkMultiProcessController* c,
  std::vector<std::vector<long long>>& outgoing, const std::vector<long long>& incomingCounts)
{
  const int me = rankOf(c), n = rankCount(c);
  std::size_t bytes = 0;
  for (int r = 0; r < n; ++r)
  {
    bytes += r == me ? 0 : outgoing[r].size() * sizeof(long long);
  }
  phases::collective(c, "exchange", bytes);
  std::vector<std::vector<long long>> incoming(n);
  incoming[me] = std::move(outgoing[me]);
  const int rounds = n > 1 ? n - 1 + n % 2 : 0;
  for (int round = 0; round < rounds; ++round)
  {
    const int p = partnerInRound(me, n, round);
    if (p < 0)
    {
      continue;
    }
    incoming[p].resize(static_cast<std::size_t>(incomingCounts[p]));
    const auto send = [&] {
      if (!outgoing[p].empty())
      {
        c->Send(outgoing[p].data(), static_cast<vtkIdType>(outgoing[p].size()), p, kExchangeTag);
      }
    };
    const auto receive = [&] {
      if (!incoming[p].empty())
      {
        c->Receive(incoming[p].data(), static_cast<vtkIdType>(incoming[p].size()), p, kExchangeTag);
      }
    };
    if (me < p)
    {
      send();
      receive();
    }
    else
    {
      receive();
      send();
    }
  }
  return incoming;
}

// The length every rank will send to this one, from every rank's lengths
// to every rank (all-gathered: P^2 numbers, 32 KB at 64 ranks).
std::vector<long long> lengthsToMe(vtkMultiProcessController* c, const std::vector<std::vector<long long>>& outgoing)
{
  const int me = rankOf(c), n = rankCount(c);
  std::vector<long long> mine(n);
  for (int r = 0; r < n; ++r)
  {
    mine[r] = static_cast<long long>(outgoing[r].size());
  }
  const std::vector<long long> all = gather(c, mine, nullptr);
  std::vector<long long> toMe(n);
  for (int r = 0; r < n; ++r)
  {
    toMe[r] = all[static_cast<std::size_t>(r) * n + me];
  }
  return toMe;
}
/// @}
} // namespace

std::vector<long long> minimumOverHolders(vtkMultiProcessController* c, long long keyCount,
  const std::vector<long long>& keys, const std::vector<long long>& values)
{
  const int n = rankCount(c);
  // (key, value) pairs to the rank that settles each key, and where each came from
  std::vector<std::vector<long long>> pairs(n);
  std::vector<std::vector<std::size_t>> from(n);
  for (std::size_t i = 0; i < keys.size(); ++i)
  {
    // clamped, so a key outside [0, keyCount) cannot index past `pairs`: it
    // is still settled by one rank, the same on every rank that holds it
    const long long spread = static_cast<long long>(static_cast<__int128>(keys[i]) * n / std::max(keyCount, 1LL));
    const int settler = static_cast<int>(std::clamp<long long>(spread, 0, n - 1));
    pairs[settler].push_back(keys[i]);
    pairs[settler].push_back(values[i]);
    from[settler].push_back(i);
  }
  const std::vector<long long> pairLengths = lengthsToMe(c, pairs);
  std::vector<std::vector<long long>> received = exchangeWithRanks(c, pairs, pairLengths);
  std::unordered_map<long long, long long> smallest;
  for (const std::vector<long long>& r : received)
  {
    for (std::size_t j = 0; j < r.size(); j += 2)
    {
      auto [it, inserted] = smallest.emplace(r[j], r[j + 1]);
      it->second = inserted ? it->second : std::min(it->second, r[j + 1]);
    }
  }
  std::vector<std::vector<long long>> answers(n);
  for (int r = 0; r < n; ++r)
  {
    for (std::size_t j = 0; j < received[r].size(); j += 2)
    {
      answers[r].push_back(smallest[received[r][j]]);
    }
  }
  std::vector<long long> answerLengths(n);
  for (int r = 0; r < n; ++r)
  {
    answerLengths[r] = static_cast<long long>(from[r].size());
  }
  const std::vector<std::vector<long long>> back = exchangeWithRanks(c, answers, answerLengths);
  std::vector<long long> result(keys.size());
  for (int r = 0; r < n; ++r)
  {
    for (std::size_t j = 0; j < from[r].size(); ++j)
    {
      result[from[r][j]] = back[r][j];
    }
  }
  return result;
}

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
