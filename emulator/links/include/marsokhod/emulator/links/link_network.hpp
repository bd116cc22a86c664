// Every link of a platform, built from its wiring, each at its wire's speed.
#pragma once

#include "marsokhod/emulator/kernel/kernel.hpp"
#include "marsokhod/emulator/links/link.hpp"
#include "marsokhod/emulator/platform/platform.hpp"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace marsokhod::emulator {

class Node;

/// Every link of a platform, built from its wiring, each at its wire's speed. Ends at nodes
/// or devices that are not powered start dead; a broken wire carries nothing.
class LinkNetwork {
public:
  /// `speed_override_mbps` replaces every wire's speed (what-if runs, linktest --mbps).
  LinkNetwork(Kernel& kernel, const PlatformSpec& platform,
              std::optional<int> speed_override_mbps = std::nullopt);

  /// The port at link `link` of node or device `owner`, nullptr when nothing is wired there.
  LinkPort* port(const std::string& owner, int link);
  /// As port(), but a missing wire is an error naming the endpoint.
  LinkPort& require_port(const std::string& owner, int link);
  /// Connects the node's link ports to its wires (Node::attach_link), so that its power
  /// switch reaches them.
  void attach(Node& node);
  /// Powers every link end of a node or device on or off.
  void set_powered(const std::string& owner, bool powered);
  /// Breaks or mends the wire at an endpoint.
  void set_broken(const std::string& owner, int link, bool broken);

  const std::vector<std::unique_ptr<Link>>& links() const { return links_; }

private:
  std::vector<std::unique_ptr<Link>> links_;
  std::map<std::pair<std::string, int>, LinkPort*> ports_;
};

} // namespace marsokhod::emulator
