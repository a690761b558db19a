#include "kernel/network/network_json.hpp"

#include <cmath>
#include <set>

#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/json_input.hpp"

namespace rigidfold {

namespace {

using nlohmann::json;

std::string at(const std::string& source, const std::string& path) {
  std::string s = source;
  s += ": ";
  s += path;
  return s;
}

void only_keys(const json& obj, const std::set<std::string>& allowed, const std::string& source, const std::string& path) {
  for (auto it = obj.begin(); it != obj.end(); ++it)
    if (!allowed.count(it.key())) {
      std::string p = path.empty() ? it.key() : path + "." + it.key();
      throw InputError(at(source, p), "unknown key");
    }
}

double degrees(const json& v, const std::string& source, const std::string& path, double limit) {
  if (!v.is_number()) throw InputError(at(source, path), "must be a number (degrees)");
  const double d = v.get<double>();
  if (!std::isfinite(d) || std::fabs(d) > limit) {
    std::string what = "must be a finite number of degrees in [-";
    what += std::to_string(static_cast<int>(limit));
    what += ", ";
    what += std::to_string(static_cast<int>(limit));
    what += "]";
    throw InputError(at(source, path), what);
  }
  return to_radians(d);
}

std::string name_of(const json& v, const std::string& source, const std::string& path) {
  if (!v.is_string() || v.get<std::string>().empty()) throw InputError(at(source, path), "must be a non-empty joint name");
  return v.get<std::string>();
}

}  // namespace

NetworkSpec parse_network_json(const json& doc, const std::string& source) {
  if (!doc.is_object()) throw InputError(source, "the network must be a JSON object");
  only_keys(doc, {"description", "linkages", "input", "outputs", "guess_deg"}, source, "");
  NetworkSpec spec;
  if (doc.contains("description")) {
    if (!doc["description"].is_string()) throw InputError(at(source, "description"), "must be a string");
    spec.description = doc["description"].get<std::string>();
  }
  if (!doc.contains("linkages")) throw InputError(at(source, "linkages"), "missing");
  const json& ls = doc["linkages"];
  if (!ls.is_array() || ls.empty()) throw InputError(at(source, "linkages"), "must be a non-empty array");
  if (ls.size() > static_cast<std::size_t>(kMaxNetworkLinkages))
    throw InputError(at(source, "linkages"), "more than 200 linkages");
  LinkageNetwork& net = spec.network;
  for (std::size_t k = 0; k < ls.size(); ++k) {
    std::string lp = "linkages[";
    lp += std::to_string(k);
    lp += "]";
    const json& l = ls[k];
    if (!l.is_object()) throw InputError(at(source, lp), "must be an object");
    only_keys(l, {"name", "twists_deg", "joints"}, source, lp);
    NetworkLinkage linkage;
    linkage.name = l.contains("name") ? name_of(l["name"], source, lp + ".name") : std::to_string(k);
    if (!l.contains("twists_deg")) throw InputError(at(source, lp + ".twists_deg"), "missing");
    if (!l.contains("joints")) throw InputError(at(source, lp + ".joints"), "missing");
    const json& tw = l["twists_deg"];
    const json& js = l["joints"];
    if (!tw.is_array() || tw.size() < 3 || tw.size() > static_cast<std::size_t>(kMaxLinkageJoints))
      throw InputError(at(source, lp + ".twists_deg"), "must be an array of 3 to 16 twists");
    if (!js.is_array() || js.size() != tw.size())
      throw InputError(at(source, lp + ".joints"), "must be an array with one joint per twist");
    std::set<int> here;
    for (std::size_t i = 0; i < tw.size(); ++i) {
      std::string ip = lp + ".twists_deg[";
      ip += std::to_string(i);
      ip += "]";
      linkage.twists.push_back(degrees(tw[i], source, ip, 360.0));
      std::string jp = lp + ".joints[";
      jp += std::to_string(i);
      jp += "]";
      const json& jr = js[i];
      NetworkJointRef ref;
      std::string name;
      if (jr.is_object()) {
        only_keys(jr, {"joint", "sign", "offset_deg"}, source, jp);
        if (!jr.contains("joint")) throw InputError(at(source, jp + ".joint"), "missing");
        name = name_of(jr["joint"], source, jp + ".joint");
        if (jr.contains("sign")) {
          const json& s = jr["sign"];
          if (!s.is_number() || (s.get<double>() != 1.0 && s.get<double>() != -1.0))
            throw InputError(at(source, jp + ".sign"), "must be 1 or -1");
          ref.sign = s.get<double>();
        }
        if (jr.contains("offset_deg")) ref.offset = degrees(jr["offset_deg"], source, jp + ".offset_deg", 360.0);
      } else {
        name = name_of(jr, source, jp);
      }
      int j = net.joint_index(name);
      if (j < 0) {
        j = net.num_joints();
        net.joint_names.push_back(name);
      }
      if (!here.insert(j).second) throw InputError(at(source, jp), "joint '" + name + "' appears twice in this linkage");
      ref.joint = j;
      linkage.joints.push_back(ref);
    }
    net.linkages.push_back(std::move(linkage));
  }
  const int n = net.num_joints();
  auto joint_of = [&](const json& v, const std::string& path) {
    const std::string name = name_of(v, source, path);
    const int j = net.joint_index(name);
    if (j < 0) throw InputError(at(source, path), "no linkage has joint '" + name + "'");
    return j;
  };
  if (doc.contains("input")) {
    const json& in = doc["input"];
    if (!in.is_object()) throw InputError(at(source, "input"), "must be an object");
    only_keys(in, {"joint", "start_deg", "end_deg"}, source, "input");
    if (!in.contains("joint")) throw InputError(at(source, "input.joint"), "missing");
    spec.input = joint_of(in["joint"], "input.joint");
    if (in.contains("start_deg")) spec.input_start = degrees(in["start_deg"], source, "input.start_deg", 360.0);
    if (in.contains("end_deg")) {
      spec.has_end = true;
      spec.input_end = degrees(in["end_deg"], source, "input.end_deg", 360.0);
    }
  }
  if (doc.contains("outputs")) {
    const json& outs = doc["outputs"];
    if (!outs.is_array()) throw InputError(at(source, "outputs"), "must be an array of joint names");
    for (std::size_t i = 0; i < outs.size(); ++i) {
      std::string p = "outputs[";
      p += std::to_string(i);
      p += "]";
      spec.outputs.push_back(joint_of(outs[i], p));
    }
  } else {
    for (int j = 0; j < n; ++j) spec.outputs.push_back(j);
  }
  spec.guess = Eigen::VectorXd::Zero(n);
  if (doc.contains("guess_deg")) {
    const json& g = doc["guess_deg"];
    if (!g.is_object()) throw InputError(at(source, "guess_deg"), "must be an object {joint: degrees}");
    for (auto it = g.begin(); it != g.end(); ++it) {
      std::string p = "guess_deg.";
      p += it.key();
      const int j = net.joint_index(it.key());
      if (j < 0) throw InputError(at(source, p), "no linkage has this joint");
      spec.guess[j] = degrees(it.value(), source, p, 360.0);
    }
  }
  spec.guess[spec.input] = spec.input_start;
  validate_network(net);  // the parser above already guarantees it; a bug if this throws
  return spec;
}

NetworkSpec read_network_json(const std::string& path) {
  return parse_network_json(parse_json_input(read_input_file(path), path), path);
}

}  // namespace rigidfold
