// Starts `adair lsp` for .air files. The server does all the work: this
// client only says which files are AdaIR and where the executable is.
"use strict";

const vscode = require("vscode");
const { LanguageClient } = require("vscode-languageclient/node");

let client;

function activate(context) {
  const command = vscode.workspace.getConfiguration("adair").get("path") || "adair";
  const server = { command, args: ["lsp"] };
  client = new LanguageClient(
    "adair",
    "AdaIR",
    { run: server, debug: server },
    {
      documentSelector: [{ scheme: "file", language: "adair" }],
    }
  );
  context.subscriptions.push(client);
  return client.start();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
