// The mailbox of the grid methods (§4's ray and beam tracers, §5's flux tracing and
// decahedra): a piece listed in several cells is tested once per ray or query. Each piece
// keeps the serial of the last round (a ray, a query) that saw it; a round begins by taking
// a new serial, so no stamp has to be cleared between rounds. When the serial wraps to 0
// every stamp is forgotten, so that a stamp 2^32 rounds old never passes for a new one.
// (The serial's type is a parameter so that tests can wrap it in 255 rounds.)
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace fb89::host {

template <class Serial>
class BasicMailbox {
  public:
    // One round: a view of the stamps (like a span, it writes them even when const) and the
    // round's serial. Kernels hold it by value, capture included, so that their loops keep
    // the stamps' address in a register.
    class Round {
      public:
        // True the first time `piece` is seen in this round.
        bool first_visit(uint32_t piece) const {
            if (m_stamp[piece] == m_serial) return false;
            m_stamp[piece] = m_serial;
            return true;
        }

      private:
        friend class BasicMailbox;
        Round(Serial* stamp, Serial serial) : m_stamp(stamp), m_serial(serial) {}
        Serial* m_stamp;
        Serial m_serial;
    };

    explicit BasicMailbox(size_t pieces = 0) : m_stamp(pieces, 0) {}
    size_t size() const { return m_stamp.size(); }
    // More pieces, unseen; a round begun before is no longer valid.
    void grow(size_t pieces) {
        if (pieces > m_stamp.size()) m_stamp.resize(pieces, 0);
    }

    // Starts a round with a new serial; forgets every stamp when the serial wraps.
    Round begin() {
        if (++m_serial == 0) {
            std::fill(m_stamp.begin(), m_stamp.end(), 0);
            m_serial = 1;
        }
        return {m_stamp.data(), m_serial};
    }

  private:
    std::vector<Serial> m_stamp;  // per piece: the serial of the last round that saw it
    Serial m_serial = 0;
};

using Mailbox = BasicMailbox<uint32_t>;

}  // namespace fb89::host
