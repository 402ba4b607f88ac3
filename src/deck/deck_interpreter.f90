!> The deck evaluator: runs the statements of a parsed deck in the language of
!> doc/deck-language.md (Python 3's semantics for what decks write) and dispatches each
!> command call to its registered handler.
!>
!> A deck is evaluated twice (design.md): the check pass (ctx%checking) evaluates every
!> expression and validates every command against the catalog, producing placeholder
!> concepts (or running side-effect-free handlers registered with at_check); the run pass
!> then evaluates again and runs each command. Integer/real arithmetic follows Python 3 and
!> every operation is checked before it is done (no FP trap, located errors instead).
!>
!> This module holds the interfaces (shared declarations in deck_interp_base); the work is
!> split by concern into submodules: deck_interp_statements (files, statements, assignment,
!> loops), deck_interp_expressions (expressions, comprehensions, f-strings, slices),
!> deck_interp_operators (operators, comparisons), deck_interp_values (items, iteration,
!> truth, text, equality, order), deck_interp_calls (calls, def functions, attributes and
!> methods, commands), deck_interp_builtins and deck_interp_math (the built-in functions),
!> deck_interp_strings and deck_interp_formatting (the methods of strings, % and
!> str.format), deck_interp_types (the methods of lists, dicts, tuples and _F) and
!> deck_interp_imports (imports).
module deck_interpreter
    use kinds, only: dp, i4, i8
    use strings, only: string_t, to_text
    use status, only: status_t, set_error, STATUS_DECK_ERROR
    use deck_ast
    use deck_value
    use run_context, only: run_context_t
    use deck_interp_base
    implicit none
    private

    public :: load_deck, deck_from_text, evaluate_deck, eval_expression, call_def_values
    public :: read_source_text, load_source, evaluate_session, flat_value

    interface
        ! ---- deck_interp_statements ----
        module subroutine load_deck(ctx, st)
            type(run_context_t), intent(inout) :: ctx
            type(status_t), intent(out) :: st
        end subroutine load_deck
        module subroutine read_source_text(path, what, text, st)
            character(len=*), intent(in) :: path, what
            character(len=:), allocatable, intent(out) :: text
            type(status_t), intent(out) :: st
        end subroutine read_source_text
        module subroutine deck_from_text(ctx, text, st)
            type(run_context_t), intent(inout) :: ctx
            character(len=*), intent(in) :: text
            type(status_t), intent(out) :: st
        end subroutine deck_from_text
        module subroutine load_source(ctx, text, name, dir, module, k, st)
            type(run_context_t), intent(inout) :: ctx
            character(len=*), intent(in) :: text, name, dir, module
            integer, intent(out) :: k
            type(status_t), intent(out) :: st
        end subroutine load_source
        module subroutine evaluate_session(ctx, st)
            type(run_context_t), intent(inout) :: ctx
            type(status_t), intent(out) :: st
        end subroutine evaluate_session
        module subroutine evaluate_deck(ctx, st)
            type(run_context_t), intent(inout) :: ctx
            type(status_t), intent(out) :: st
        end subroutine evaluate_deck
        module recursive subroutine exec_statement(ctx, id, st, frame)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            type(status_t), intent(inout) :: st
            type(frame_t), intent(inout), optional, target :: frame
        end subroutine exec_statement
        module recursive subroutine exec_block(ctx, block, st, frame)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: block
            type(status_t), intent(inout) :: st
            type(frame_t), intent(inout), optional, target :: frame
        end subroutine exec_block
        module recursive subroutine assign_target(ctx, target, v, st, frame)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: target
            type(value_t), intent(in) :: v
            type(status_t), intent(inout) :: st
            type(frame_t), intent(inout), optional, target :: frame
        end subroutine assign_target
        module subroutine bind_name(ctx, id, name, v, frame)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            character(len=*), intent(in) :: name
            type(value_t), intent(in) :: v
            type(frame_t), intent(inout), optional :: frame
        end subroutine bind_name
        module subroutine stop_check(ctx, id)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
        end subroutine stop_check
        module subroutine next_iteration(ctx, id, st)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            type(status_t), intent(inout) :: st
        end subroutine next_iteration

        ! ---- deck_interp_expressions ----
        module subroutine eval_expression(ctx, id, v, st)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            type(value_t), intent(out) :: v
            type(status_t), intent(out) :: st
        end subroutine eval_expression
        module recursive subroutine eval(ctx, id, v, st, frame, target)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            type(value_t), intent(out) :: v
            type(status_t), intent(inout) :: st
            type(frame_t), intent(inout), optional, target :: frame
            character(len=*), intent(in), optional :: target
        end subroutine eval
        module subroutine lookup(ctx, id, v, st, frame)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            type(value_t), intent(out) :: v
            type(status_t), intent(inout) :: st
            type(frame_t), intent(in), optional, target :: frame
        end subroutine lookup
        module recursive subroutine binary(ctx, id, op, a, b, v, st, in_place)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            character(len=*), intent(in) :: op
            type(value_t), intent(in) :: a, b
            type(value_t), intent(out) :: v
            type(status_t), intent(inout) :: st
            logical, intent(in), optional :: in_place
        end subroutine binary
        module recursive subroutine get_item(ctx, id, seq, index, v, st)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            type(value_t), intent(in) :: seq, index
            type(value_t), intent(out) :: v
            type(status_t), intent(inout) :: st
        end subroutine get_item
        module recursive subroutine set_item(ctx, id, seq, index, v, st)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            type(value_t), intent(in) :: seq, index, v
            type(status_t), intent(inout) :: st
        end subroutine set_item
        module recursive subroutine iterate(ctx, id, v, items, st)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            type(value_t), intent(in) :: v
            type(value_t), allocatable, intent(out) :: items(:)
            type(status_t), intent(inout) :: st
        end subroutine iterate
        module logical function is_true(ctx, v)
            type(run_context_t), intent(in) :: ctx
            type(value_t), intent(in) :: v
        end function is_true
        module recursive function text_of(ctx, v, repr, depth) result(text)
            type(run_context_t), intent(in) :: ctx
            type(value_t), intent(in) :: v
            logical, intent(in) :: repr
            integer, intent(in), optional :: depth
            character(len=:), allocatable :: text
        end function text_of
        module recursive logical function values_equal(ctx, a, b) result(same)
            type(run_context_t), intent(in) :: ctx
            type(value_t), intent(in) :: a, b
        end function values_equal
        module recursive subroutine order(ctx, id, a, b, c, st)
            type(run_context_t), intent(in) :: ctx
            integer, intent(in) :: id
            type(value_t), intent(in) :: a, b
            integer, intent(out) :: c
            type(status_t), intent(inout) :: st
        end subroutine order
        module recursive subroutine format_value(ctx, id, v, spec, text, st)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            type(value_t), intent(in) :: v
            character(len=*), intent(in) :: spec
            character(len=:), allocatable, intent(out) :: text
            type(status_t), intent(inout) :: st
        end subroutine format_value

        module function characters(s) result(chars)
            character(len=*), intent(in) :: s
            type(value_t), allocatable :: chars(:)
        end function characters
        module recursive subroutine unary(ctx, id, a, v, st)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            type(value_t), intent(in) :: a
            type(value_t), intent(out) :: v
            type(status_t), intent(inout) :: st
        end subroutine unary
        module recursive subroutine compare_pair(ctx, id, op, a, b, r, st)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            character(len=*), intent(in) :: op
            type(value_t), intent(in) :: a, b
            type(value_t), intent(out) :: r
            type(status_t), intent(inout) :: st
        end subroutine compare_pair
        module recursive subroutine compare_chain(ctx, id, v, st, frame)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            type(value_t), intent(out) :: v
            type(status_t), intent(inout) :: st
            type(frame_t), intent(inout), optional, target :: frame
        end subroutine compare_chain

        ! ---- deck_interp_calls ----
        module recursive subroutine eval_call(ctx, id, v, st, frame, target)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            type(value_t), intent(out) :: v
            type(status_t), intent(inout) :: st
            type(frame_t), intent(inout), optional, target :: frame
            character(len=*), intent(in), optional :: target
        end subroutine eval_call
        module recursive subroutine call_value(ctx, id, f, args, kwargs, v, st, frame)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            type(value_t), intent(in) :: f
            type(value_t), intent(in) :: args(:), kwargs
            type(value_t), intent(out) :: v
            type(status_t), intent(inout) :: st
            type(frame_t), intent(inout), optional, target :: frame
        end subroutine call_value
        module recursive subroutine call_def_values(ctx, def_node, args, v, st, call_id, frame)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: def_node, call_id
            type(value_t), intent(in) :: args(:)
            type(value_t), intent(out) :: v
            type(status_t), intent(inout) :: st
            type(frame_t), intent(inout), optional, target :: frame
        end subroutine call_def_values
        module recursive subroutine get_attribute(ctx, id, obj, name, v, st)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            type(value_t), intent(in) :: obj
            character(len=*), intent(in) :: name
            type(value_t), intent(out) :: v
            type(status_t), intent(inout) :: st
        end subroutine get_attribute
        module recursive subroutine call_method(ctx, id, obj, name, args, kwargs, v, st, frame)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            type(value_t), intent(in) :: obj
            character(len=*), intent(in) :: name
            type(value_t), intent(in) :: args(:), kwargs
            type(value_t), intent(out) :: v
            type(status_t), intent(inout) :: st
            type(frame_t), intent(inout), optional, target :: frame
        end subroutine call_method
        module recursive subroutine use_attribute(ctx, id, obj, name, called, args, kwargs, &
                                                  v, st)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            type(value_t), intent(in) :: obj
            character(len=*), intent(in) :: name
            logical, intent(in) :: called
            type(value_t), intent(in) :: args(:), kwargs
            type(value_t), intent(out) :: v
            type(status_t), intent(inout) :: st
        end subroutine use_attribute
        module logical function has_method(ctx, v, name)
            type(run_context_t), intent(in) :: ctx
            type(value_t), intent(in) :: v
            character(len=*), intent(in) :: name
        end function has_method

        module recursive subroutine run_catalog_command(ctx, id, name, kwargs, v, st)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            character(len=*), intent(in) :: name
            type(value_t), intent(in) :: kwargs
            type(value_t), intent(out) :: v
            type(status_t), intent(inout) :: st
        end subroutine run_catalog_command

        ! ---- deck_interp_builtins ----
        module recursive subroutine call_builtin(ctx, id, name, args, kwargs, v, st, frame)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            character(len=*), intent(in) :: name
            type(value_t), intent(in) :: args(:), kwargs
            type(value_t), intent(out) :: v
            type(status_t), intent(inout) :: st
            type(frame_t), intent(inout), optional, target :: frame
        end subroutine call_builtin
        module pure logical function is_builtin(name)
            character(len=*), intent(in) :: name
        end function is_builtin
        module subroutine round_value(ctx, id, args, v, st)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            type(value_t), intent(in) :: args(:)
            type(value_t), intent(out) :: v
            type(status_t), intent(inout) :: st
        end subroutine round_value
        module subroutine call_math(ctx, id, name, args, kwargs, v, st)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            character(len=*), intent(in) :: name
            type(value_t), intent(in) :: args(:), kwargs
            type(value_t), intent(out) :: v
            type(status_t), intent(inout) :: st
        end subroutine call_math
        module recursive subroutine sort_items(ctx, id, items, kwargs, st, frame)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            type(value_t), intent(inout) :: items(:)
            type(value_t), intent(in) :: kwargs
            type(status_t), intent(inout) :: st
            type(frame_t), intent(inout), optional, target :: frame
        end subroutine sort_items

        ! ---- deck_interp_types ----
        module recursive subroutine type_method(ctx, id, obj, name, args, kwargs, v, st, frame)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            type(value_t), intent(in) :: obj
            character(len=*), intent(in) :: name
            type(value_t), intent(in) :: args(:), kwargs
            type(value_t), intent(out) :: v
            type(status_t), intent(inout) :: st
            type(frame_t), intent(inout), optional, target :: frame
        end subroutine type_method
        module pure logical function type_has_method(kind, name)
            integer, intent(in) :: kind
            character(len=*), intent(in) :: name
        end function type_has_method
        module recursive subroutine str_method(ctx, id, s, name, args, kwargs, v, st)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            character(len=*), intent(in) :: s, name
            type(value_t), intent(in) :: args(:), kwargs
            type(value_t), intent(out) :: v
            type(status_t), intent(inout) :: st
        end subroutine str_method
        module recursive subroutine str_format(ctx, id, template, args, kwargs, text, st)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            character(len=*), intent(in) :: template
            type(value_t), intent(in) :: args(:), kwargs
            character(len=:), allocatable, intent(out) :: text
            type(status_t), intent(inout) :: st
        end subroutine str_format
        module recursive subroutine percent_format(ctx, id, template, arg, text, st)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            character(len=*), intent(in) :: template
            type(value_t), intent(in) :: arg
            character(len=:), allocatable, intent(out) :: text
            type(status_t), intent(inout) :: st
        end subroutine percent_format

        ! ---- deck_interp_testcase ----
        module recursive subroutine testcase_method(ctx, id, obj, name, called, args, kwargs, &
                                                    v, st)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            type(value_t), intent(in) :: obj
            character(len=*), intent(in) :: name
            logical, intent(in) :: called
            type(value_t), intent(in) :: args(:), kwargs
            type(value_t), intent(out) :: v
            type(status_t), intent(inout) :: st
        end subroutine testcase_method
        module subroutine new_testcase(ctx, id, args, kwargs, v, st)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            type(value_t), intent(in) :: args(:), kwargs
            type(value_t), intent(out) :: v
            type(status_t), intent(inout) :: st
        end subroutine new_testcase

        ! ---- deck_interp_macros ----
        module subroutine cata_builtin(ctx, id, name, args, kwargs, v, st)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            character(len=*), intent(in) :: name
            type(value_t), intent(in) :: args(:), kwargs
            type(value_t), intent(out) :: v
            type(status_t), intent(inout) :: st
        end subroutine cata_builtin
        module recursive subroutine call_user_macro(ctx, id, f, args, kwargs, v, st, frame)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            type(value_t), intent(in) :: f
            type(value_t), intent(in) :: args(:), kwargs
            type(value_t), intent(out) :: v
            type(status_t), intent(inout) :: st
            type(frame_t), intent(inout), optional, target :: frame
        end subroutine call_user_macro

        ! ---- deck_interp_medutils ----
        module subroutine split_med_file(ctx, id, args, kwargs, v, st)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            type(value_t), intent(in) :: args(:), kwargs
            type(value_t), intent(out) :: v
            type(status_t), intent(inout) :: st
        end subroutine split_med_file

        ! ---- deck_interp_imports ----
        module recursive subroutine exec_import(ctx, id, st, frame)
            type(run_context_t), intent(inout) :: ctx
            integer, intent(in) :: id
            type(status_t), intent(inout) :: st
            type(frame_t), intent(inout), optional :: frame
        end subroutine exec_import
    end interface

contains

    !> A flat copy of v: lists and dicts as values of their own (deck_heap%flatten), for
    !> what reads the deck's values outside the interpreter (unit tests, messages).
    function flat_value(ctx, v) result(flat)
        type(run_context_t), intent(in) :: ctx
        type(value_t), intent(in) :: v
        type(value_t) :: flat
        character(len=:), allocatable :: message
        call ctx%heap%flatten(v, flat, message)
    end function flat_value

end module deck_interpreter
