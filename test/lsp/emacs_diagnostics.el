;;; Run by test_emacs.rb in Emacs in batch mode, after the editor guide's
;;; configuration (loaded first, as init.el would be): opens a file,
;;; starts eglot on it as `M-x eglot' does, waits for the diagnostics
;;; Flymake shows for the file and writes them as JSON to a file the test
;;; reads. Usage: emacs --batch -q -l init.el -l emacs_diagnostics.el FILE OUT

(require 'eglot)
(require 'json)

(let* ((file (nth 0 command-line-args-left))
       (out (nth 1 command-line-args-left))
       (buffer (find-file-noselect file))
       (deadline (+ (float-time) 20))
       (diagnostics nil))
  (setq command-line-args-left nil)
  (switch-to-buffer buffer)
  ;; What M-x eglot runs: the server for the buffer's mode, from
  ;; eglot-server-programs.
  (apply #'eglot (eglot--guess-contact))
  (while (and (null diagnostics) (< (float-time) deadline))
    (accept-process-output nil 0.1)
    ;; Batch mode has no command loop, whose idle timers start Flymake's
    ;; checks in an interactive Emacs.
    (when (bound-and-true-p flymake-mode) (flymake-start))
    (setq diagnostics (flymake-diagnostics)))
  (let ((shown (with-current-buffer buffer
                 (mapcar (lambda (d)
                           `((line . ,(1- (line-number-at-pos (flymake-diagnostic-beg d))))
                             (type . ,(symbol-name (flymake-diagnostic-type d)))
                             (text . ,(flymake-diagnostic-text d))))
                         diagnostics)))
        (server (with-current-buffer buffer (eglot-current-server))))
    (with-temp-file out
      (insert (json-encode `((server . ,(and server (eglot--project-nickname server)))
                             (diagnostics . ,(vconcat shown))))))))
(kill-emacs 0)
