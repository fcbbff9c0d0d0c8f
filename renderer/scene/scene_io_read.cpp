// The reading steps scene_io's scene and lighting readers share (see scene_io_read.h).
#include "scene/scene_io_read.h"

namespace wavelit::scene {

using util::ErrorKind;
using util::makeError;

util::Error problemsError(const std::string& file, std::vector<std::string> problems, const util::Error* hard) {
    if (hard) problems.push_back(hard->file == file ? util::Error{hard->kind, "", hard->where, hard->reason}.message()
                                                    : hard->message());
    std::string reason;
    if (problems.size() == 1) {
        reason = problems[0];
    } else {
        reason = std::to_string(problems.size()) + " problems:";
        for (const std::string& p : problems) reason += "\n  " + p;
    }
    return makeError(ErrorKind::Invalid, file, reason);
}

void checkKeys(const Json& obj, const std::vector<std::string>& known, const JsonPlace& at,
               std::vector<std::string>& problems) {
    for (auto it = obj.begin(); it != obj.end(); ++it)
        if (std::find(known.begin(), known.end(), it.key()) == known.end())
            problems.push_back(unknownKeyProblem(it.key(), at, known));
}

util::Status readRootExtras(const Json& obj, const JsonPlace& at, std::string* extras) {
    auto it = obj.find("extras");
    return it == obj.end() ? util::okStatus() : readExtras(*it, at.child("extras"), extras);
}

util::Result<std::string> readName(const Json& doc, const JsonPlace& at) {
    auto it = doc.find("name");
    if (it == doc.end()) return std::string();
    if (!it->is_string()) return jsonError(ErrorKind::Format, at.child("name"), std::string("name: expected a string, got ") + jsonTypeName(*it));
    return it->get<std::string>();
}

} // namespace wavelit::scene
