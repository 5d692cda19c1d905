// The mailbox: a piece is seen once per round, every round starts fresh, and the serial's
// wrap-around forgets every stamp (shown on an 8-bit serial, which wraps in 255 rounds).
#include "host/trace/mailbox.h"

#include <gtest/gtest.h>

namespace fb89::host {
namespace {

TEST(Mailbox, APieceIsFirstVisitedOncePerRound) {
    Mailbox mailbox(4);
    Mailbox::Round round = mailbox.begin();
    EXPECT_TRUE(round.first_visit(2));
    EXPECT_FALSE(round.first_visit(2));
    EXPECT_TRUE(round.first_visit(0));
    EXPECT_FALSE(round.first_visit(0));
}

TEST(Mailbox, ANewRoundSeesEveryPieceAgain) {
    Mailbox mailbox(3);
    Mailbox::Round first = mailbox.begin();
    for (uint32_t p = 0; p < 3; ++p)
        EXPECT_TRUE(first.first_visit(p));
    Mailbox::Round second = mailbox.begin();
    for (uint32_t p = 0; p < 3; ++p)
        EXPECT_TRUE(second.first_visit(p));
}

TEST(Mailbox, WrapAroundForgetsAStampThatWouldEqualTheNewSerial) {
    BasicMailbox<uint8_t> mailbox(2);
    EXPECT_TRUE(mailbox.begin().first_visit(1));  // round 1: piece 1 stamped with serial 1
    for (int round = 2; round <= 255; ++round)    // serials 2 .. 255, piece 0 only
        EXPECT_TRUE(mailbox.begin().first_visit(0));
    // the serial wraps to 0, every stamp is forgotten, and the round takes serial 1 again:
    // piece 1's stamp from round 1 must not pass for this round's
    BasicMailbox<uint8_t>::Round wrapped = mailbox.begin();
    EXPECT_TRUE(wrapped.first_visit(1));
    EXPECT_TRUE(wrapped.first_visit(0));
    EXPECT_FALSE(wrapped.first_visit(1));
}

TEST(Mailbox, GrowingAddsUnseenPiecesAndNeverShrinks) {
    Mailbox mailbox(1);
    mailbox.grow(3);
    EXPECT_EQ(mailbox.size(), 3u);
    EXPECT_TRUE(mailbox.begin().first_visit(2));
    mailbox.grow(2);
    EXPECT_EQ(mailbox.size(), 3u);
}

}  // namespace
}  // namespace fb89::host
