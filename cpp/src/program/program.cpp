#include "toolcomp/program/program.hpp"

namespace toolcomp {

void Program::begin_block(int line, bool block_delete) {
    Block b;
    b.line = line;
    b.block_delete = block_delete;
    b.first_word = static_cast<std::uint32_t>(words_.size());
    b.first_comment = static_cast<std::uint32_t>(comments_.size());
    b.first_token = static_cast<std::uint32_t>(tokens_.size());
    b.first_statement = static_cast<std::uint32_t>(statements_.size());
    blocks_.push_back(b);
}

void Program::drop_last_block() {
    if (blocks_.empty()) return;
    const Block& b = blocks_.back();
    words_.resize(b.first_word);
    comments_.resize(b.first_comment);
    tokens_.resize(b.first_token);
    statements_.resize(b.first_statement);
    blocks_.pop_back();
}

void Program::clear() {
    Column<Block> blocks = std::move(blocks_);
    Column<Word> words = std::move(words_);
    auto tokens = std::move(tokens_);
    std::vector<Comment> comments = std::move(comments_);
    *this = Program();
    blocks.clear();
    words.clear();
    tokens.clear();
    comments.clear();
    blocks_ = std::move(blocks);
    words_ = std::move(words);
    tokens_ = std::move(tokens);
    comments_ = std::move(comments);
}

}  // namespace toolcomp
