// What a run launched by Open MPI's mpirun leaves out of MPI_Init: the network transports when
// every rank is on this node, unless the user chose a messaging layer.

#include <gtest/gtest.h>

#include "solver/petsc_session.hpp"

namespace iga {
namespace {

TEST(MessagingLayers, NetworkTransportsLeftOutWhenEveryRankIsOnThisNode) {
  EXPECT_EQ(messaging_layers_to_skip("1", "1", nullptr, nullptr), "^cm");
  EXPECT_EQ(messaging_layers_to_skip("2", "2", nullptr, nullptr), "^cm");
  EXPECT_EQ(messaging_layers_to_skip("64", "64", nullptr, nullptr), "^cm");
}

TEST(MessagingLayers, KeptAcrossNodesOrWhenChosen) {
  EXPECT_EQ(messaging_layers_to_skip("4", "2", nullptr, nullptr), "");  // two nodes: the network carries messages
  EXPECT_EQ(messaging_layers_to_skip("12", "2", nullptr, nullptr), "");
  EXPECT_EQ(messaging_layers_to_skip("2", "2", "ob1", nullptr), "");   // mpirun --mca pml ob1
  EXPECT_EQ(messaging_layers_to_skip("2", "2", "cm", nullptr), "");
  EXPECT_EQ(messaging_layers_to_skip("2", "2", nullptr, "psm2"), "");  // an MTL needs the cm layer
  EXPECT_EQ(messaging_layers_to_skip(nullptr, nullptr, nullptr, nullptr), "");  // not Open MPI's mpirun
  EXPECT_EQ(messaging_layers_to_skip("2", nullptr, nullptr, nullptr), "");
}

}  // namespace
}  // namespace iga
