#ifndef PTM_PIPELINE_REQUESTS_H
#define PTM_PIPELINE_REQUESTS_H
// The pipeline requests every filter of the plugin makes alike, written once.
//
// The readers put the whole surface on piece 0 (the others stay empty); the
// surface filters (AlphaWrap, VolumeBalancedCutter) ask their upstream for
// the whole surface on every rank, piece 0 of 1, so a reader reads the file
// on every rank and a bad file fails on every rank alike (when an upstream
// fails on one rank only, VTK's executive skips the filter on that rank alone
// and the others would wait for it forever); every output announces that it
// produces any piece asked of it.
#include "vtkAlgorithm.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <fstream>

namespace ptm
{
// Every output port of `outputVector` can produce any piece.
inline void announceAnyPiece(vtkInformationVector* outputVector)
{
  for (int port = 0; port < outputVector->GetNumberOfInformationObjects(); ++port)
  {
    outputVector->GetInformationObject(port)->Set(vtkAlgorithm::CAN_HANDLE_PIECE_REQUEST(), 1);
  }
}

// Input `port` asks for the whole data set: piece 0 of 1, no ghost levels
// (nothing when nothing is connected to it).
inline void requestWholeInput(vtkInformationVector** inputVector, int port = 0)
{
  vtkInformation* inInfo = inputVector[port]->GetInformationObject(0);
  if (!inInfo)
  {
    return;
  }
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
}

// The piece asked of an output (0 when none is asked).
inline int requestedPiece(vtkInformation* outInfo)
{
  return outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER())
    ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER())
    : 0;
}

// A reader's CanReadFile: the file can be opened (its content is judged,
// with a message, when it is read).
inline int fileOpens(const char* fileName)
{
  if (!fileName || !*fileName)
  {
    return 0;
  }
  std::ifstream in(fileName);
  return in.is_open() ? 1 : 0;
}
} // namespace ptm
#endif
