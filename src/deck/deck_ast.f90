!> Abstract syntax tree of a deck: a flat pool of nodes that refer to their children by
!> index (no pointers, no recursive types). Every node keeps the line and column of the token
!> that starts it, so every later error can be located in the deck.
module deck_ast
    use kinds, only: i4
    use strings, only: string_t
    implicit none
    private

    !> Node kinds. Expressions:
    integer, parameter, public :: N_INT = 1, N_REAL = 2, N_STR = 3, N_NAME = 4, N_TUPLE = 5, &
        N_LIST = 6, N_UNARY = 7, N_BINOP = 8, N_COMPARE = 9, N_AND = 10, N_OR = 11, &
        N_IFEXP = 12, N_CALL = 13, N_KWARG = 14
    !> Statements:
    integer, parameter, public :: N_MODULE = 20, N_ASSIGN = 21, N_EXPR = 22, N_DEF = 23, &
        N_IF = 24, N_RETURN = 25, N_BLOCK = 26, N_PASS = 27, N_FOR = 28, N_BREAK = 29, &
        N_CONTINUE = 30, N_IMPORT = 31, N_FROM_IMPORT = 32
    !> Indexing, slicing and attributes (expressions):
    integer, parameter, public :: N_INDEX = 15, N_SLICE = 16, N_ATTR = 17
    !> Displays, f-strings, comprehensions, lambdas and argument unpacking (expressions):
    integer, parameter, public :: N_DICT = 18, N_FSTRING = 19, N_LISTCOMP = 40, &
        N_DICTCOMP = 41, N_GENEXP = 42, N_COMPFOR = 43, N_STARRED = 44, N_DSTAR = 45, &
        N_FORMAT = 46, N_LAMBDA = 47, N_SLICEITEM = 48
    !> More statements:
    integer, parameter, public :: N_ASSIGN_MULTI = 33, N_AUGASSIGN = 34, N_WHILE = 35, &
        N_DEL = 36, N_ASSERT = 37, N_RAISE = 38

    !> One node. `text` holds the name, operator, literal spelling or string value.
    !> Children by kind:
    !>   N_UNARY(op: '-', '+', 'not') [operand];  N_BINOP(op) [left, right]
    !>   N_COMPARE(ops blank-separated, e.g. '< <=') [operands...]
    !>   N_AND / N_OR [operands...];  N_IFEXP [value if true, condition, value if false]
    !>   N_CALL [callee, arguments...] (keyword arguments are N_KWARG(name) [value])
    !>   N_TUPLE / N_LIST [items...]
    !>   N_ASSIGN(name) [value]: `name = value`;  N_EXPR [value];  N_RETURN [value]
    !>   N_ASSIGN_MULTI [targets..., value]: `a, b = ...`, `x[i] = ...`, `a = b = ...`
    !>     (a target: N_NAME, N_TUPLE/N_LIST of targets, N_INDEX, N_SLICE, N_ATTR)
    !>   N_AUGASSIGN(op: '+', '-', ...) [target, value]: `target op= value`
    !>   N_DEF(name) [parameters..., N_BLOCK body]: a parameter is N_NAME(name) [default?],
    !>     N_STARRED(name) for *args, N_DSTAR(name) for **kwargs
    !>   N_LAMBDA [parameters..., body expression]
    !>   N_IF [condition, then, else?];  N_WHILE [condition, body, else?]
    !>   N_DEL [targets...];  N_ASSERT [condition, message?];  N_RAISE [exception?]
    !>   N_MODULE / N_BLOCK [statements...]
    !>   N_DICT [key, value, key, value...] (a `**d` entry: the same N_DSTAR node twice)
    !>   N_FSTRING [parts...]: N_STR literal text, or N_FORMAT(conversion: '', 'r', 's',
    !>     'a') [expression, spec?] with spec an N_FSTRING
    !>   N_LISTCOMP / N_GENEXP [element, N_COMPFOR...];  N_DICTCOMP [key, value, N_COMPFOR...]
    !>   N_COMPFOR [target, iterable, conditions...]
    !>   N_STARRED [value] (*x in a call or a display);  N_DSTAR [value] (**d in a call)
    !>   N_SLICEITEM(parts as N_SLICE's) [bounds...]: a slice inside a tuple index x[:, 0]
    !>   N_INDEX [sequence, index];  N_ATTR(attribute) [object] (obj.name, a concept's
    !>     method or attribute; as a callee, obj.name(...); L.append as a statement)
    !>   N_SLICE(parts) [sequence, start?, stop?, step?]: parts is 3 characters, '1' where
    !>     start, stop, step are written ('010' for s[:j]), the written ones are the children
    !>   N_FOR(variable, or '' for another target) [target, sequence, N_BLOCK body, else?]
    !>   N_BREAK;  N_CONTINUE
    !>   N_IMPORT [N_NAME(dotted module) [N_NAME(alias)?]...]
    !>   N_FROM_IMPORT(dotted module) [N_NAME(name or '*') [N_NAME(alias)?]...]
    type, public :: node_t
        integer(i4) :: kind = 0
        character(len=:), allocatable :: text
        integer(i4) :: line = 0, col = 0
        integer(i4) :: end_line = 0          !< statements: last source line
        integer(i4) :: file = 0              !< source file (ast%files), 0 if unknown
        integer(i4), allocatable :: kids(:)  !< exactly the children once sealed
        integer(i4) :: nk = 0                !< children while building
    end type node_t

    !> The node pool; node 1..n. `root` is the N_MODULE node of a parsed deck. Several
    !> source files (the command files of a session, imported modules) share one pool;
    !> each node records its file (files(node%file)), so any node can be located.
    type, public :: ast_t
        type(node_t), allocatable :: nodes(:)
        integer(i4) :: n = 0
        integer(i4) :: root = 0
        type(string_t), allocatable :: files(:)   !< file names as used in messages
        integer(i4) :: current_file = 0           !< file of the nodes being added
    contains
        procedure :: add => ast_add
        procedure :: use_file => ast_use_file
        procedure :: file_name => ast_file_name
        procedure :: add_kid => ast_add_kid
        procedure :: nkids => ast_nkids
        procedure :: kid => ast_kid
        procedure :: seal => ast_seal
    end type ast_t

contains

    !> Appends a node and returns its index.
    !>  kind : N_* kind;  text : name/operator/literal;  line, col : source position
    function ast_add(self, kind, text, line, col) result(id)
        class(ast_t), intent(inout) :: self
        integer, intent(in) :: kind, line, col
        character(len=*), intent(in) :: text
        integer :: id
        type(node_t), allocatable :: bigger(:)
        character(len=:), allocatable :: copy
        copy = text          ! text may be a node's own text: the pool may move below
        if (.not. allocated(self%nodes)) allocate (self%nodes(256))
        if (self%n == size(self%nodes)) then
            allocate (bigger(2 * size(self%nodes)))
            bigger(1:self%n) = self%nodes(1:self%n)
            call move_alloc(bigger, self%nodes)
        end if
        self%n = self%n + 1
        id = self%n
        self%nodes(id)%kind = kind
        call move_alloc(copy, self%nodes(id)%text)
        self%nodes(id)%line = line
        self%nodes(id)%col = col
        self%nodes(id)%end_line = line
        self%nodes(id)%file = self%current_file
        allocate (self%nodes(id)%kids(0))
    end function ast_add

    !> Makes `name` the file of the nodes added from now on (registered on first use).
    subroutine ast_use_file(self, name)
        class(ast_t), intent(inout) :: self
        character(len=*), intent(in) :: name
        type(string_t), allocatable :: bigger(:)
        integer :: k
        if (.not. allocated(self%files)) allocate (self%files(0))
        do k = 1, size(self%files)
            if (self%files(k)%s == name) then
                self%current_file = int(k, i4)
                return
            end if
        end do
        allocate (bigger(size(self%files) + 1))
        do k = 1, size(self%files)
            bigger(k)%s = self%files(k)%s
        end do
        bigger(size(bigger))%s = name
        call move_alloc(bigger, self%files)
        self%current_file = int(size(self%files), i4)
    end subroutine ast_use_file

    !> The file name of node `id` ('' if unknown).
    function ast_file_name(self, id) result(name)
        class(ast_t), intent(in) :: self
        integer, intent(in) :: id
        character(len=:), allocatable :: name
        integer :: f
        name = ''
        if (id < 1 .or. id > self%n) return
        f = self%nodes(id)%file
        if (f < 1) return
        if (f > size(self%files)) return
        name = self%files(f)%s
    end function ast_file_name

    !> Appends `child` to the children of `parent` (amortized: capacity doubles; `seal`
    !> trims the arrays when the parse is complete).
    subroutine ast_add_kid(self, parent, child)
        class(ast_t), intent(inout) :: self
        integer, intent(in) :: parent, child
        integer(i4), allocatable :: bigger(:)
        associate (node => self%nodes(parent))
            if (node%nk == size(node%kids)) then
                allocate (bigger(max(4, 2 * node%nk)))
                bigger(1:node%nk) = node%kids(1:node%nk)
                call move_alloc(bigger, node%kids)
            end if
            node%nk = node%nk + 1
            node%kids(node%nk) = int(child, i4)
        end associate
    end subroutine ast_add_kid

    !> Trims the children arrays of nodes first..n to their exact size.
    subroutine ast_seal(self, first)
        class(ast_t), intent(inout) :: self
        integer, intent(in) :: first
        integer :: id
        do id = max(first, 1), self%n
            if (size(self%nodes(id)%kids) /= self%nodes(id)%nk) &
                self%nodes(id)%kids = self%nodes(id)%kids(1:self%nodes(id)%nk)
        end do
    end subroutine ast_seal

    !> Number of children of node `id`.
    pure integer function ast_nkids(self, id)
        class(ast_t), intent(in) :: self
        integer, intent(in) :: id
        ast_nkids = self%nodes(id)%nk
    end function ast_nkids

    !> The k-th child of node `id`.
    pure integer function ast_kid(self, id, k)
        class(ast_t), intent(in) :: self
        integer, intent(in) :: id, k
        ast_kid = self%nodes(id)%kids(k)
    end function ast_kid

end module deck_ast
