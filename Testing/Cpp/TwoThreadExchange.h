#ifndef PTM_TEST_TWO_THREAD_EXCHANGE_H
#define PTM_TEST_TWO_THREAD_EXCHANGE_H
// Two threads as the two processes of a collective call, for the tests of
// the stages that share work among ranks (the relaxer's crossing check, the
// cutter's checks): each thread calls exchange(process, mine) once per
// round and both get combine(what process 0 gave, what process 1 gave)
// once both have arrived, as an MPI all-gather or all-reduce would give.
#include <condition_variable>
#include <functional>
#include <mutex>
#include <utility>

namespace ptm::test
{
template <typename T>
class TwoThreadExchange
{
public:
  explicit TwoThreadExchange(std::function<T(const T&, const T&)> combine)
    : Combine(std::move(combine))
  {
  }

  T exchange(int process, const T& mine)
  {
    std::unique_lock<std::mutex> lock(this->Mutex);
    const long generation = this->Generation;
    this->Slots[process] = mine;
    if (++this->Arrived == 2)
    {
      this->All = this->Combine(this->Slots[0], this->Slots[1]);
      this->Arrived = 0;
      ++this->Generation;
      this->Changed.notify_all();
      return this->All;
    }
    this->Changed.wait(lock, [&] { return this->Generation != generation; });
    return this->All;
  }

private:
  std::function<T(const T&, const T&)> Combine;
  std::mutex Mutex;
  std::condition_variable Changed;
  T Slots[2];
  T All;
  int Arrived = 0;
  long Generation = 0;
};
} // namespace ptm::test
#endif
